// SPDX-License-Identifier: Zlib
#pragma once
// Hertzian impact of two elastic bodies (paper §5.1; Johnson, Contact Mechanics §11.4; Popov
// 2010 ch. 5): contact duration and peak force from the effective modulus, radius and mass.
//
//   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  1/R* = k1 + k2 (k = 1/R, mean curvature),
//   1/m* = 1/m1 + 1/m2,
//   t_c   = 2.8683 (m*^2 / (E*^2 R* v))^(1/5)                          [s]
//   F_max = 1.2827 E*^(2/5) R*^(1/5) m*^(3/5) v^(6/5)                   [N]
//
// Limits (never 0, inf or NaN for valid input):
//   - approach speed v below kMinApproachSpeed (1 mm/s, resting contact) uses that floor; logged
//     once per process;
//   - R* above the caller's radius cap (flat-on-flat contact has k1 + k2 = 0, i.e. R* = inf) is
//     capped; logged once per process. The world passes the fracturing body's characteristic
//     length (cube root of its volume) as the cap: a contact patch cannot be wider than the body.
//   - Negative curvature (concave contact) counts as flat: the convex partner then sets R*.
namespace btfracture {

// Floor for the normal approach speed [m/s]; below it a contact is resting, not an impact.
constexpr double kMinApproachSpeed = 1e-3;

struct HertzBody {
    double youngsModulus = 0.0;  // E [Pa], > 0
    double poissonRatio = 0.0;   // nu, in (-1, 0.5)
    double inverseMass = 0.0;    // 1/m [1/kg], 0 for a static or kinematic body
    double curvature = 0.0;      // mean curvature 1/R at the contact [1/m]; 0 for a flat face
};

struct HertzImpact {
    double effectiveModulus = 0.0;  // E* [Pa]
    double effectiveRadius = 0.0;   // R* [m], after the cap
    double effectiveMass = 0.0;     // m* [kg]
    double approachSpeed = 0.0;     // v [m/s], after the floor
    double contactDuration = 0.0;   // t_c [s]
    double peakForce = 0.0;         // F_max [N]
    bool speedFloored = false;      // v was raised to kMinApproachSpeed
    bool radiusCapped = false;      // R* was lowered to the cap
};

// Throws btfracture::Error naming the bad value when a modulus, Poisson ratio, curvature,
// inverse mass, speed or radius cap is out of range or non-finite, or when both bodies have
// infinite mass (no impact possible).
HertzImpact hertzImpact(const HertzBody& a, const HertzBody& b, double approachSpeed, double radiusCap);

}  // namespace btfracture
