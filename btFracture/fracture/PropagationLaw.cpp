// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/PropagationLaw.h>

#include <btFracture/core/PortableMath.h>

#include <algorithm>
#include <cmath>

namespace btfracture {

namespace {
const double kMaxKink = pmath::acos(1.0 / 3.0);  // 70.53 degrees
}

double kinkAngle(double KI, double KII) {
    if (KII == 0.0) return KI >= 0.0 ? 0.0 : kMaxKink;
    if (KI <= 0.0) return KII > 0.0 ? -kMaxKink : kMaxKink;
    return 2.0 * pmath::atan((KI - std::sqrt(KI * KI + 8.0 * KII * KII)) / (4.0 * KII));
}

double modeRatioForKink(double theta) {
    const double t = pmath::tan(0.5 * theta);
    return t / (2.0 * t * t - 1.0);
}

double effectiveK(double KI, double KII, double KIII, double nu) {
    return std::sqrt(KI * KI + KII * KII + KIII * KIII / (1.0 - nu));
}

FrontAdvance advanceOf(const FrontSifs& f, double toughness, double compressiveFactor, double nu, double step,
                       double minimumSpeed) {
    FrontAdvance out;
    const double Keff = effectiveK(f.KI, f.KII, f.KIII, nu);
    const double Kc = f.compressive ? toughness * compressiveFactor : toughness;
    if (!(Keff > Kc)) return out;
    out.angle = kinkAngle(f.KI, f.KII);
    out.direction = pmath::cos(out.angle) * f.frame.ahead + pmath::sin(out.angle) * f.frame.normal;
    out.distance = step * std::max(minimumSpeed, 1.0 - (Kc * Kc) / (Keff * Keff));
    return out;
}

}  // namespace btfracture
