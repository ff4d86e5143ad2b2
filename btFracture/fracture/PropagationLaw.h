// SPDX-License-Identifier: Zlib
#pragma once
// How far and in which direction a crack front point moves in one step (paper §4.2 and the
// propagation of Hahn & Wojtan 2015): maximum hoop stress direction (Patricio & Mattheij 2007),
// growth where the effective K exceeds the toughness, speed below the Rayleigh speed.
#include <btFracture/fracture/StressIntensity.h>

namespace btfracture {

// Kink angle theta [rad] of the maximum hoop stress criterion, measured from the ahead
// direction m towards the crack normal n (paper §4.2):
//   theta = 2 atan[(K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)].
// Pure mode II gives -/+ 70.5 degrees; a closed crack (K_I <= 0) kinks by that limit too.
double kinkAngle(double KI, double KII);

// K_II / K_I that makes the criterion kink by theta (paper §4.2, inverse of kinkAngle):
// r = tan(theta/2) / (2 tan^2(theta/2) - 1), valid for cos(theta) >= 1/3.
double modeRatioForKink(double theta);

// sqrt(K_I^2 + K_II^2 + K_III^2 / (1 - nu)): equal energy release rate in plane strain.
double effectiveK(double KI, double KII, double KIII, double poissonRatio);

struct FrontAdvance {
    double distance = 0.0;                                // [m]; 0 = the point does not move
    double angle = 0.0;                                   // kink angle [rad]
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit, in the plane of m and n
};

// One step of length up to `step` [m]: d = step (1 - (K_c / K_eff)^2), at least minimumSpeed
// * step, where K_eff > K_c (K_c scaled by the compressive factor for compressive fronts).
FrontAdvance advanceOf(const FrontSifs& sifs, double toughness, double compressiveFactor, double poissonRatio,
                       double step, double minimumSpeed);

}  // namespace btfracture
