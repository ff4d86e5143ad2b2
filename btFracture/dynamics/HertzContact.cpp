// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/HertzContact.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/PortableMath.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

// t_c = 2.9432 alpha*/v with 2.9432 = 2 int_0^1 (1 - x^(5/2))^(-1/2) dx and
// alpha* = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5) give 2.9432 (15/16)^(2/5) = 2.8683 (FractureRB's
// 2.868265699195); F_max = (4/3) E* sqrt(R*) alpha*^(3/2) gives (4/3) (15/16)^(3/5) = 1.2827.
constexpr double kDurationConstant = 2.868265699195;
const double kPeakForceConstant = 4.0 / 3.0 * pmath::pow(15.0 / 16.0, 0.6);

std::atomic<bool> speedFloorLogged{false};
std::atomic<bool> radiusCapLogged{false};

void requireBody(const HertzBody& body, const char* which) {
    std::ostringstream problem;
    if (!(body.youngsModulus > 0.0) || !std::isfinite(body.youngsModulus))
        problem << "Young's modulus " << body.youngsModulus << " Pa (need > 0)";
    else if (!(body.poissonRatio > -1.0 && body.poissonRatio < 0.5))
        problem << "Poisson ratio " << body.poissonRatio << " (need -1 < nu < 0.5)";
    else if (!(body.inverseMass >= 0.0) || !std::isfinite(body.inverseMass))
        problem << "inverse mass " << body.inverseMass << " 1/kg (need >= 0)";
    else if (!std::isfinite(body.curvature))
        problem << "curvature " << body.curvature << " 1/m (need finite)";
    if (problem.tellp() > 0) throw Error(std::string("hertzImpact: body ") + which + ": " + problem.str());
}

}  // namespace

HertzImpact hertzImpact(const HertzBody& a, const HertzBody& b, double approachSpeed, double radiusCap) {
    requireBody(a, "a");
    requireBody(b, "b");
    if (!(approachSpeed >= 0.0) || !std::isfinite(approachSpeed)) {
        std::ostringstream out;
        out << "hertzImpact: approach speed " << approachSpeed << " m/s (need finite, >= 0)";
        throw Error(out.str());
    }
    if (!(radiusCap > 0.0) || !std::isfinite(radiusCap)) {
        std::ostringstream out;
        out << "hertzImpact: radius cap " << radiusCap << " m (need finite, > 0)";
        throw Error(out.str());
    }
    const double inverseMass = a.inverseMass + b.inverseMass;
    if (!(inverseMass > 0.0))
        throw Error("hertzImpact: both bodies have infinite mass (static or kinematic)");

    HertzImpact h;
    h.effectiveModulus = 1.0 / ((1.0 - a.poissonRatio * a.poissonRatio) / a.youngsModulus +
                                (1.0 - b.poissonRatio * b.poissonRatio) / b.youngsModulus);
    h.effectiveMass = 1.0 / inverseMass;

    const double curvature = std::max(a.curvature, 0.0) + std::max(b.curvature, 0.0);
    h.effectiveRadius = radiusCap;
    if (curvature * radiusCap > 1.0) {
        h.effectiveRadius = 1.0 / curvature;
    } else {
        h.radiusCapped = true;
        if (!radiusCapLogged.exchange(true))
            logf(LogLevel::Info, "Hertz contact: effective radius capped at ", radiusCap,
                 " m for a flat or nearly flat contact (curvature sum ", curvature,
                 " 1/m); reported once per process");
    }

    h.approachSpeed = approachSpeed;
    if (approachSpeed < kMinApproachSpeed) {
        h.approachSpeed = kMinApproachSpeed;
        h.speedFloored = true;
        if (!speedFloorLogged.exchange(true))
            logf(LogLevel::Info, "Hertz contact: approach speed ", approachSpeed, " m/s raised to the floor ",
                 kMinApproachSpeed, " m/s (resting contact); reported once per process");
    }

    const double m = h.effectiveMass, E = h.effectiveModulus, R = h.effectiveRadius, v = h.approachSpeed;
    h.contactDuration = kDurationConstant * pmath::pow(m * m / (E * E * R * v), 0.2);
    h.peakForce = kPeakForceConstant * pmath::pow(E, 0.4) * pmath::pow(R, 0.2) * pmath::pow(m, 0.6) *
                  pmath::pow(v, 1.2);
    return h;
}

}  // namespace btfracture
