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

#include <vector>

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
// `crackArea` [m^2]: K_I^2 + K_II^2 = (lambda k (pi A)^(1/4))^2 with the chosen eigenvalue lambda
// (§4.2). K_I is positive; a compressive choice is flagged in `compressive` (its threshold is
// then the compressive toughness, PropagationLaw.h; the factor enters here only through the choice).
FrontSifs estimateSifs(const FrontFrame& frame, const Eigen::Matrix3d& stress, double crackArea,
                       double compressiveFactor, double geometryFactor);

// What the load can produce: a crack of size a under stresses of at most sigma_peak has
// K <= F sigma_peak sqrt(pi a) with a geometry factor F that no handbook geometry takes far
// beyond kMaxGeometryFactor (the edge crack of Tada's formula reaches 6 at a / b = 0.7). EST's
// K = k lambda (pi A)^(1/4) stays within that bound when lambda <= kMaxGeometryFactor / k times
// the largest principal stress magnitude on the body's crack-free surface (where the stress of a
// body loaded only on its surface peaks), `peak` [Pa]. boundStress scales a larger local stress
// (the interior integral near the surface, or the §4.3 update piling up openings) down to
// that, keeping its directions, and returns whether it did.
constexpr double kMaxGeometryFactor = 6.0;
bool boundStress(Eigen::Matrix3d& stress, double peak);
// Largest principal stress magnitude over `stresses` (e.g. per surface triangle) [Pa].
double peakStress(const std::vector<Eigen::Matrix3d>& stresses);

// What the load can release: the crack area a step adds, front node i advancing d_i over its
// spacing s_i (advanceOf), releases sum_i G_i s_i d_i with G = (1 - nu^2) K_eff^2 / E (plane
// strain). Under the event's fixed tractions that is the growth of the strain energy
// U = 1/2 integral t.u dA (Clapeyron), which within one step cannot exceed U itself unless the
// step more than doubles the body's compliance. Returns the factor kappa in (0, 1] by which all
// SIFs must be scaled (same mode mix, so the same kink) for the release to equal `strainEnergy`
// [J], or 1 where it stays below; `toughness` [Pa m^(1/2)] per entry of `sifs`, `step` [m].
double energyBoundScale(const std::vector<FrontSifs>& sifs, const std::vector<double>& toughness,
                        double youngsModulus, double poissonRatio, double compressiveFactor, double step,
                        double minimumSpeed, double strainEnergy);

// The energy the bound above may release [J]: the tractions' strain energy U, but no more than
// the contacts can deliver. An impact stores at most the kinetic energy of its approach (the
// quasi-static load J / t_c lasts only the contact time), `kinetic` = sum 1/2 m* v^2 (reduced
// mass, normal approach speed); resting contacts add the strain energy `resting` of their own
// tractions.
double deliverableEnergy(double strainEnergy, double kinetic, double resting);

}  // namespace btfracture
