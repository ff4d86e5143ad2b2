// SPDX-License-Identifier: Zlib
#include <btFracture/core/PortableMath.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

// The double-double steps below (twoSum, twoProd) are exact only if every product is rounded
// on its own: this file must be compiled with -ffp-contract=off (the project's default flags).

namespace btfracture::pmath {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint64_t bitsOf(double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
}

double fromBits(std::uint64_t u) {
    double x;
    std::memcpy(&x, &u, sizeof x);
    return x;
}

// x rounded to the nearest integer, ties to even, for |x| < 2^51: adding 1.5 2^52 leaves no
// fraction bits.
double roundToInteger(double x) {
    return (x + 0x1.8p52) - 0x1.8p52;
}

// 2^k for -1022 <= k <= 1023.
double twoTo(int k) {
    return fromBits(static_cast<std::uint64_t>(k + 1023) << 52);
}

// y 2^k for -1100 < k <= 1024 and y in [0.5, 2], rounded once (subnormal results included).
double scaleByTwoTo(double y, int k) {
    if (k > 1023) return y * 2.0 * twoTo(1023);
    if (k >= -1022) return y * twoTo(k);
    return y * twoTo(k + 1000) * twoTo(-1000);  // the first product is exact
}

// x with the low 32 bits of its significand cleared: a 21-bit head whose square is exact.
double head21(double x) {
    return fromBits(bitsOf(x) & 0xffffffff00000000ULL);
}

// x = m 2^k with m in (sqrt(1/2), sqrt(2)]; x positive, finite, non-zero.
double splitExponent(double x, int& k) {
    k = 0;
    if (x < std::numeric_limits<double>::min()) {  // subnormal: scale into the normal range
        x *= 0x1p54;
        k = -54;
    }
    const std::uint64_t u = bitsOf(x);
    k += static_cast<int>(u >> 52) - 1023;
    double m = fromBits((u & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
    if (m > 0x1.6a09e667f3bcdp+0) {  // sqrt(2)
        m *= 0.5;
        ++k;
    }
    return m;
}

// ---- Double-double arithmetic (Dekker 1971; Knuth TAOCP vol. 2, 4.2.2) -------------------------

struct DD {
    double hi, lo;
};

// a + b = s.hi + s.lo exactly.
DD twoSum(double a, double b) {
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

// a + b = s.hi + s.lo exactly when |a| >= |b|.
DD fastTwoSum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

// a = hi + lo with 26-bit halves (|a| < 2^995).
void split(double a, double& hi, double& lo) {
    const double t = 134217729.0 * a;  // 2^27 + 1
    hi = t - (t - a);
    lo = a - hi;
}

// a b = p.hi + p.lo exactly (|a|, |b| < 2^995, no underflow).
inline DD twoProd(double a, double b) {
    double ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    const double p = a * b;
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

inline DD add(DD a, DD b) {
    const DD s = twoSum(a.hi, b.hi);
    return fastTwoSum(s.hi, s.lo + (a.lo + b.lo));
}

inline DD add(DD a, double b) {
    const DD s = twoSum(a.hi, b);
    return fastTwoSum(s.hi, s.lo + a.lo);
}

inline DD mul(DD a, DD b) {
    const DD p = twoProd(a.hi, b.hi);
    return fastTwoSum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

// ---- Constants (values to the bit; hexadecimal where the split matters) --------------------------

constexpr double kPio2Hi = 0x1.921fb54442d18p+0;  // pi/2 = kPio2Hi + kPio2Lo to 107 bits
constexpr double kPio2Lo = 0x1.1a62633145c07p-54;
constexpr double kPio4Hi = 0x1.921fb54442d18p-1;
constexpr double kPiHi = 0x1.921fb54442d18p+1;
constexpr double kPiLo = 0x1.1a62633145c07p-53;

// ln 2 = kLn2Hi + kLn2Lo to 2^-88 relative; kLn2Hi has 32 significant bits, so k kLn2Hi is exact
// for |k| < 2^21.
constexpr double kLn2Hi = 0x1.62e42ffp-1;
constexpr double kLn2Lo = -0x1.718432a1b0e26p-35;
constexpr double kInvLn2 = 0x1.71547652b82fep+0;

// ---- sin, cos, tan ------------------------------------------------------------------------------

// pi/2 = part1 + part2 + part3 + tail (Cody & Waite); the parts have 33 significant bits, so
// n part_i is exact for |n| < 2^20, which |x| < kExactReduction guarantees.
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kPio2Part1 = 0x1.921fb544p+0;
constexpr double kPio2Part2 = 0x1.0b4611a6p-34;
constexpr double kPio2Part3 = 0x1.3198a2ep-69;
constexpr double kPio2Tail = 0x1.b839a252049c1p-104;
constexpr double kExactReduction = 1.5e6;
constexpr double kTwoPi = 0x1.921fb54442d18p+2;

struct Reduced {
    DD r;          // x - n pi/2, |r| <= pi/4 (slightly more at the rounding boundaries)
    int quadrant;  // n mod 4
};

// x finite, |x| > pi/4.
Reduced reduceHalfPi(double x) {
    // Large arguments: x mod fl(2 pi), exact but not the true x mod 2 pi (documented in the header).
    if (!(std::fabs(x) < kExactReduction)) x = std::remainder(x, kTwoPi);
    const double n = roundToInteger(x * kTwoOverPi);
    const double t = x - n * kPio2Part1;  // exact: n kPio2Part1 is exact and within a factor 2 of x
    const DD a = twoSum(t, -n * kPio2Part2);
    const DD b = twoSum(a.hi, -n * kPio2Part3);
    const double tail = (a.lo + b.lo) - n * kPio2Tail;
    return {twoSum(b.hi, tail), static_cast<int>(static_cast<long long>(n) & 3)};
}

// fdlibm's __kernel_sin and __kernel_cos coefficients (Sun Microsystems 1993): minimax
// polynomials on [-pi/4, pi/4], relative error below 2^-58.
constexpr double S1 = -1.66666666666666324348e-01;
constexpr double S2 = 8.33333333332248946124e-03;
constexpr double S3 = -1.98412698298579493134e-04;
constexpr double S4 = 2.75573137070700676789e-06;
constexpr double S5 = -2.50507602534068634195e-08;
constexpr double S6 = 1.58969099521155010221e-10;
constexpr double C1 = 4.16666666666666019037e-02;
constexpr double C2 = -1.38888888888741095749e-03;
constexpr double C3 = 2.48015872894767294178e-05;
constexpr double C4 = -2.75573143513906633035e-07;
constexpr double C5 = 2.08757232129817482790e-09;
constexpr double C6 = -1.13596475577881948265e-11;

// sin(x + y) for |x| <= ~pi/4 and |y| <= ulp(x)/2: x + S1 x^3 + x^5 r(x^2), plus y cos(x) to
// first order, y (1 - x^2/2).
double sinKernel(double x, double y) {
    const double z = x * x, v = z * x;
    const double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

// cos(x + y) = 1 - x^2/2 + x^4 q(x^2) - x y; 1 - x^2/2 is summed as w + its rounding error.
double cosKernel(double x, double y) {
    const double z = x * x;
    const double r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    const double hz = 0.5 * z, w = 1.0 - hz;
    return w + (((1.0 - w) - hz) + (z * r - x * y));
}

// ---- asin, acos ---------------------------------------------------------------------------------

// fdlibm's e_asin.c rational approximation: (asin(x) - x) / x^3 ~ R(t) = P(t) / Q(t), t = x^2,
// on [0, 0.5], error below 2^-58.75.
double asinRational(double t) {
    const double p =
        t * (1.66666666666666657415e-01 +
             t * (-3.25565818622400915405e-01 +
                  t * (2.01212532134862925881e-01 +
                       t * (-4.00555345006794114027e-02 +
                            t * (7.91534994289814532176e-04 + t * 3.47933107596021167570e-05)))));
    const double q = 1.0 + t * (-2.40339491173441421878e+00 +
                                t * (2.02094576023350569471e+00 +
                                     t * (-6.88283971605453293030e-01 + t * 7.70381505559019352791e-02)));
    return p / q;
}

// ---- atan ---------------------------------------------------------------------------------------

// fdlibm's s_atan.c: atan(t) ~ t - t^3 (a0 + a1 t^2 + ... + a10 t^20) on [0, 7/16], and
// breakpoints 1/2, 1, 3/2 with atan(c) to 107 bits (hi + lo).
double atanSeries(double z) {  // z = t^2
    return z * (3.33333333333329318027e-01 +
                z * (-1.99999999998764832476e-01 +
                     z * (1.42857142725034663711e-01 +
                          z * (-1.11111104054623557880e-01 +
                               z * (9.09088713343650656196e-02 +
                                    z * (-7.69187620504482999495e-02 +
                                         z * (6.66107313738753120669e-02 +
                                              z * (-5.83357013379057348645e-02 +
                                                   z * (4.97687799461593236017e-02 +
                                                        z * (-3.65315727442169155270e-02 +
                                                             z * 1.62858201153657823623e-02))))))))));
}

constexpr double kAtanHi[] = {0x1.dac670561bb4fp-2, 0x1.921fb54442d18p-1, 0x1.f730bd281f69bp-1, kPio2Hi};
constexpr double kAtanLo[] = {0x1.a2b7f222f65e2p-56, 0x1.1a62633145c07p-55, 0x1.007887af0cbbdp-56, kPio2Lo};

// ---- exp, log -----------------------------------------------------------------------------------

constexpr double kExpOverflow = 7.09782712893383973096e+02;    // exp(x) > DBL_MAX above
constexpr double kExpUnderflow = -7.45133219101941108420e+02;  // exp(x) rounds to 0 below

// exp(h + l) for |l| <= ulp(h): fdlibm's e_exp.c. With h + l = k ln2 + r, |r| <= ln2/2, and
// c = r - r^2 (P1 + P2 r^2 + ... + P5 r^8) (minimax, error below 2^-59),
// exp(r) = 1 + r + r c / (2 - c); r is carried as hi - lo, and 1 + hi as a double-double.
double expDD(double h, double l) {
    if (h > kExpOverflow) return kInf;
    if (h < kExpUnderflow) return 0.0;
    const double k = roundToInteger(h * kInvLn2);
    const double hi = h - k * kLn2Hi;  // exact
    const double lo = k * kLn2Lo - l;
    const double r = hi - lo, t = r * r;
    const double c = r - t * (1.66666666666666019037e-01 +
                              t * (-2.77777777770155933842e-03 +
                                   t * (6.61375632143793436117e-05 +
                                        t * (-1.65339022054652515390e-06 + t * 4.13813679705723846039e-08))));
    const double corr = (r * c) / (2.0 - c);  // exp(r) - 1 - r
    const DD one = twoSum(1.0, hi);           // 1 + hi exactly: the sum is rounded once
    return scaleByTwoTo(one.hi + (one.lo + (corr - lo)), static_cast<int>(k));
}

// log(x) in double-double, relative error below 2^-69; x positive, finite, non-zero. With
// x = m 2^k, c the centre nearest m of 3/4, 1 and 5/4, and
// s = (m - c) / (m + c), |s| <= 0.0718: log(m) = log(c) + 2 atanh(s) =
// log(c) + 2 s + 2/3 s^3 + s^5 (2/5 + 2/7 z + ... + 2/17 z^6), z = s^2 <= 0.00516 (Taylor: the
// first omitted term is below 2^-70 of the sum). 2 s and 2/3 s^3 are double-doubles; the rest,
// below 2^-17 of the sum, is a double.
DD logDD(double x) {
    int k;
    const double m = splitExponent(x, k);
    constexpr double kCentre[] = {0.75, 1.0, 1.25};
    constexpr DD kLogCentre[] = {{-0x1.269621134db92p-2, -0x1.e0efadd9db02bp-56},
                                 {0.0, 0.0},
                                 {0x1.c8ff7c79a9a22p-3, -0x1.4f689f8434012p-57}};
    const int i = m < 0x1.bb67ae8584caap-1 ? 0 : m > 0x1.1e3779b97f4a8p+0 ? 2 : 1;  // sqrt(3/4), sqrt(5/4)
    const double f = m - kCentre[i];                                                // exact (Sterbenz)
    const DD d = twoSum(m, kCentre[i]);
    const double inverse = 1.0 / d.hi;
    const double sh = f * inverse;
    const DD p = twoProd(sh, d.hi);
    const double sl = (((f - p.hi) - p.lo) - sh * d.lo) * inverse;  // f / d - sh
    const DD s = fastTwoSum(sh, sl);
    const DD z = mul(s, s), s3 = mul(s, z);
    const double w = z.hi;
    const double tail =
        2.0 / 5 +
        w * (2.0 / 7 + w * (2.0 / 9 + w * (2.0 / 11 + w * (2.0 / 13 + w * (2.0 / 15 + w * (2.0 / 17))))));
    constexpr DD kTwoThirds{0x1.5555555555555p-1, 0x1.5555555555555p-55};
    const DD atanh2 = add(add({2.0 * s.hi, 2.0 * s.lo}, mul(s3, kTwoThirds)), s3.hi * w * tail);
    const double dk = k;
    return add(add(fastTwoSum(dk * kLn2Hi, dk * kLn2Lo), kLogCentre[i]), atanh2);
}

}  // namespace

double sin(double x) {
    const double a = std::fabs(x);
    if (a < 0x1p-27) return x;  // sin(x) rounds to x (keeps -0)
    if (a <= kPio4Hi) return sinKernel(x, 0.0);
    if (!(a < kInf)) return x - x;  // inf, NaN
    const Reduced v = reduceHalfPi(x);
    switch (v.quadrant) {
        case 0:
            return sinKernel(v.r.hi, v.r.lo);
        case 1:
            return cosKernel(v.r.hi, v.r.lo);
        case 2:
            return -sinKernel(v.r.hi, v.r.lo);
        default:
            return -cosKernel(v.r.hi, v.r.lo);
    }
}

double cos(double x) {
    const double a = std::fabs(x);
    if (a < 0x1p-27) return 1.0;
    if (a <= kPio4Hi) return cosKernel(x, 0.0);
    if (!(a < kInf)) return x - x;
    const Reduced v = reduceHalfPi(x);
    switch (v.quadrant) {
        case 0:
            return cosKernel(v.r.hi, v.r.lo);
        case 1:
            return -sinKernel(v.r.hi, v.r.lo);
        case 2:
            return -cosKernel(v.r.hi, v.r.lo);
        default:
            return sinKernel(v.r.hi, v.r.lo);
    }
}

// tan = sin / cos on the reduced argument (-cos / sin in odd quadrants): within 2 ulp.
double tan(double x) {
    const double a = std::fabs(x);
    if (a < 0x1p-27) return x;
    if (a <= kPio4Hi) return sinKernel(x, 0.0) / cosKernel(x, 0.0);
    if (!(a < kInf)) return x - x;
    const Reduced v = reduceHalfPi(x);
    const double s = sinKernel(v.r.hi, v.r.lo), c = cosKernel(v.r.hi, v.r.lo);
    return (v.quadrant & 1) ? -c / s : s / c;
}

// asin(x) = x + x^3 R(x^2) for |x| < 1/2; beyond, asin(x) = pi/2 - 2 asin(sqrt((1 - |x|)/2)),
// with sqrt split into a 21-bit head and a correction below 0.975 (fdlibm e_asin.c).
double asin(double x) {
    const double a = std::fabs(x);
    if (!(a <= 1.0)) return x != x ? x + x : kNaN;
    if (a == 1.0) return x * kPio2Hi;
    if (a < 0.5) {
        if (a < 0x1p-26) return x;
        return x + x * asinRational(x * x);
    }
    const double t = 0.5 * (1.0 - a), s = std::sqrt(t), r = asinRational(t);
    double result;
    if (a >= 0.975) {
        result = kPio2Hi - (2.0 * (s + s * r) - kPio2Lo);
    } else {
        const double f = head21(s), c = (t - f * f) / (s + f);  // f + c = sqrt(t)
        result = kPio4Hi - ((2.0 * s * r - (kPio2Lo - 2.0 * c)) - (kPio4Hi - 2.0 * f));
    }
    return x > 0.0 ? result : -result;
}

// acos(x) = pi/2 - (x + x^3 R(x^2)) for |x| < 1/2; acos(x) = 2 asin(sqrt((1 - x)/2)) for x >= 1/2
// and pi - 2 asin(sqrt((1 + x)/2)) for x <= -1/2 (fdlibm e_acos.c).
double acos(double x) {
    const double a = std::fabs(x);
    if (!(a <= 1.0)) return x != x ? x + x : kNaN;
    if (x == 1.0) return 0.0;
    if (x == -1.0) return kPiHi;
    if (a < 0.5) {
        if (a <= 0x1p-57) return kPio2Hi;
        return kPio2Hi - (x - (kPio2Lo - x * asinRational(x * x)));
    }
    if (x < 0.0) {
        const double t = 0.5 * (1.0 + x), s = std::sqrt(t);
        return kPiHi - 2.0 * (s + (asinRational(t) * s - kPiLo * 0.5));
    }
    const double t = 0.5 * (1.0 - x), s = std::sqrt(t);
    const double f = head21(s), c = (t - f * f) / (s + f);  // f + c = sqrt(t)
    return 2.0 * (f + (asinRational(t) * s + c));
}

// Reduction to |t| < 7/16 around the breakpoints c = 1/2, 1, 3/2, inf:
// atan(x) = atan(c) + atan((x - c) / (1 + c x)) (fdlibm s_atan.c).
double atan(double x) {
    const double a = std::fabs(x);
    if (x != x) return x + x;
    if (a >= 0x1p66) return x > 0.0 ? kPio2Hi : -kPio2Hi;
    if (a < 0.4375) {
        if (a < 0x1p-27) return x;
        return x - x * atanSeries(x * x);
    }
    int id;
    double t;
    if (a < 0.6875) {
        id = 0;
        t = (2.0 * a - 1.0) / (2.0 + a);
    } else if (a < 1.1875) {
        id = 1;
        t = (a - 1.0) / (a + 1.0);
    } else if (a < 2.4375) {
        id = 2;
        t = (a - 1.5) / (1.0 + 1.5 * a);
    } else {
        id = 3;
        t = -1.0 / a;
    }
    const double z = kAtanHi[id] - ((t * atanSeries(t * t) - kAtanLo[id]) - t);
    return x < 0.0 ? -z : z;
}

// Quadrants and the zero/infinity cases of C99 Annex F; otherwise atan(|y / x|) placed in the
// quadrant, with pi carried as kPiHi + kPiLo (fdlibm e_atan2.c).
double atan2(double y, double x) {
    if (x != x || y != y) return x + y;
    if (x == 1.0) return atan(y);
    const bool yNeg = std::signbit(y), xNeg = std::signbit(x);
    if (y == 0.0) return xNeg ? (yNeg ? -kPiHi : kPiHi) : y;
    if (x == 0.0) return yNeg ? -kPio2Hi : kPio2Hi;
    const double ax = std::fabs(x), ay = std::fabs(y);
    if (ax == kInf) {
        double z;
        if (ay == kInf)
            z = xNeg ? 3.0 * kPio4Hi : kPio4Hi;
        else
            z = xNeg ? kPiHi : 0.0;
        return yNeg ? -z : z;
    }
    if (ay == kInf) return yNeg ? -kPio2Hi : kPio2Hi;
    const int exponentGap = static_cast<int>(bitsOf(ay) >> 52) - static_cast<int>(bitsOf(ax) >> 52);
    if (exponentGap > 60) return yNeg ? -kPio2Hi : kPio2Hi;  // |y / x| > 2^60
    // |y / x| < 2^-60 on the negative x side: pi - 0
    const double z = xNeg && exponentGap < -60 ? 0.0 : atan(ay / ax);
    if (!xNeg) return yNeg ? -z : z;
    const double r = kPiHi - (z - kPiLo);
    return yNeg ? -r : r;
}

double exp(double x) {
    if (x != x) return x + x;
    if (std::fabs(x) < 0x1p-28) return 1.0 + x;
    return expDD(x, 0.0);
}

// log(x) = k ln2 + log(1 + f) with 1 + f in (sqrt(1/2), sqrt(2)], s = f / (2 + f) and
// log(1 + f) = f - (f^2/2 - s (f^2/2 + R(s^2))), R a minimax polynomial with error below
// 2^-58.45 (fdlibm e_log.c coefficients Lg1..Lg7).
double log(double x) {
    if (x != x) return x + x;
    if (x < 0.0) return kNaN;
    if (x == 0.0) return -kInf;
    if (x == kInf) return x;
    int k;
    const double f = splitExponent(x, k) - 1.0;
    const double s = f / (2.0 + f), z = s * s;
    const double R =
        z * (6.666666666666735130e-01 +
             z * (3.999999999940941908e-01 +
                  z * (2.857142874366239149e-01 +
                       z * (2.222219843214978396e-01 +
                            z * (1.818357216161805012e-01 +
                                 z * (1.531383769920937332e-01 + z * 1.479819860511658591e-01))))));
    const double hfsq = 0.5 * f * f, dk = k;
    return dk * kLn2Hi - ((hfsq - (s * (hfsq + R) + dk * kLn2Lo)) - f);
}

// log10(x) = log(x) / ln 10 with both factors in double-double: rounded once, so that
// log10(10^n) = n exactly.
double log10(double x) {
    if (x != x) return x + x;
    if (x < 0.0) return kNaN;
    if (x == 0.0) return -kInf;
    if (x == kInf) return x;
    constexpr DD kInvLn10{0x1.bcb7b1526e50ep-2, 0x1.95355baaafad3p-57};
    return mul(logDD(x), kInvLn10).hi;
}

// x^y = exp(y log|x|) with log|x| in double-double and y log|x| as a double-double product, so
// that the result is within about 1 ulp even for |y log x| near 700.
double pow(double x, double y) {
    if (y == 0.0 || x == 1.0) return 1.0;
    if (x != x || y != y) return x + y;
    const double ax = std::fabs(x), ay = std::fabs(y);
    // 0: y is not an integer; 1: an odd integer; 2: an even integer (every |y| >= 2^53 is even)
    int yParity = 0;
    if (ay >= 0x1p53)
        yParity = 2;
    else if (std::floor(y) == y)
        yParity = (static_cast<long long>(y) & 1) ? 1 : 2;
    if (ay == kInf) {
        if (ax == 1.0) return 1.0;  // (-1)^(+-inf)
        return (ax > 1.0) == (y > 0.0) ? kInf : 0.0;
    }
    if (ax == 0.0 || ax == kInf) {
        const double r = (ax == 0.0) == (y < 0.0) ? kInf : 0.0;
        return (yParity == 1 && std::signbit(x)) ? -r : r;
    }
    double sign = 1.0;
    if (x < 0.0) {
        if (yParity == 0) return kNaN;
        if (yParity == 1) sign = -1.0;
    }
    const DD l = logDD(ax);
    const double estimate = y * l.hi;
    if (estimate > 2.0 * kExpOverflow) return sign * kInf;  // keeps twoProd's operands in range
    if (estimate < 2.0 * kExpUnderflow) return sign * 0.0;
    const DD p = twoProd(y, l.hi);
    const DD e = fastTwoSum(p.hi, p.lo + y * l.lo);
    return sign * expDD(e.hi, e.lo);
}

}  // namespace btfracture::pmath
