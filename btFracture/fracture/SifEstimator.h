// SPDX-License-Identifier: Zlib
#pragma once
// EST: stress intensity factors estimated from the local, non-singular stress at a front point
// (paper §4.2), so that no crack unknowns are solved for. K_I : K_II is chosen so that the
// maximum hoop stress kink aligns the crack normal with an eigenvector of the stress (this
// removes the oscillating paths of the plain estimate), and the magnitude follows the edge crack
// formula K = k lambda sqrt(pi a) with the equivalent length a = sqrt(A / pi) of the crack area A:
//   K_I^2 + K_II^2 = (lambda k (pi A)^(1/4))^2,  K_III = k (t . sigma n) (pi A)^(1/4).
#include <btFracture/fracture/StressIntensity.h>

#include <Eigen/Core>

namespace btfracture {

struct EstimatorChoice {
    int eigenvector = -1;  // 0 smallest .. 2 largest eigenvalue of the stress
    double eigenvalue = 0.0;
    double kink = 0.0;  // theta [rad]
    bool compressive = false;
};

// Chooses the eigenvector (§4.2): the largest eigenvalue's if its kink is admissible
// (cos theta >= 1/3), otherwise whichever of the second largest and the most negative (divided
// by the compressive factor) is larger in magnitude and admissible, otherwise the remaining one.
EstimatorChoice chooseEigenvector(const FrontFrame& frame, const Eigen::Matrix3d& stress,
                                  double compressiveFactor);

// Estimated SIFs at a front point with frame `frame`, local stress `stress` [Pa] and crack area
// `crackArea` [m^2]. K_I is positive; a compressive choice is flagged in `compressive`.
FrontSifs estimateSifs(const FrontFrame& frame, const Eigen::Matrix3d& stress, double crackArea,
                       double compressiveFactor, double geometryFactor);

}  // namespace btfracture
