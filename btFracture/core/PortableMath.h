// SPDX-License-Identifier: Zlib
#pragma once
// Double-precision elementary functions whose results depend on the argument alone.
//
// glibc chooses, at run time, FMA/AVX2 variants of exp, log, log10, pow, sin, cos, tan, atan,
// atan2, asin and acos on CPUs that have FMA, and those round differently from the SSE2 variants:
// the same binary then broke bodies differently on different CPUs. These functions use only IEEE
// basic operations (+ - * / sqrt, comparisons, exact exponent manipulation), compiled with
// -ffp-contract=off, so they give the same bits on every x86-64 CPU. Every btFracture call of
// those functions goes through here; the float functions (sinf, ...) and sqrt, cbrt, hypot,
// which glibc computes the same way on every CPU, stay std::.
//
// Algorithms: fdlibm's (Sun Microsystems, 1993), with its published minimax coefficients; pow and
// log10 evaluate log(x) in double-double arithmetic and round once at the end. Errors against the
// exact result (20,000 arguments each, checked with mpmath): sin, cos, asin, acos, atan, log at
// most 0.85 ulp (fdlibm's bound is 1 ulp), tan 2 ulp (a quotient of sin and cos), exp and pow
// 0.63 ulp, log10 0.5 ulp; relative error below 4e-16 everywhere. tests/core/
// test_portable_math.cpp compares them with glibc over dense sweeps.
//
// sin, cos, tan reduce the argument by pi/2 held to 152 bits (Cody & Waite: three 33-bit parts
// and a tail), exactly for |x| < 1.5e6. Larger arguments are first reduced exactly modulo the
// double nearest 2 pi: deterministic and bounded, but with an absolute error up to 4e-17 |x|.
//
// Special values follow C99 Annex F: NaN in gives NaN; sin(+-0) = +-0; sin(+-inf) = NaN; asin and
// acos of |x| > 1 and log of x < 0 give NaN; log(+-0) = -inf; exp overflows to +inf and underflows
// through the subnormals to +0; pow handles x < 0 with integer y, signed zeros and infinities.
namespace btfracture::pmath {

double sin(double x);
double cos(double x);
double tan(double x);
double asin(double x);
double acos(double x);
double atan(double x);
double atan2(double y, double x);
double exp(double x);
double log(double x);
double log10(double x);
double pow(double x, double y);

}  // namespace btfracture::pmath
