// SPDX-License-Identifier: Zlib
// Cost of the portable elementary functions (core/PortableMath.h) against glibc's, which picks
// FMA/AVX2 variants on this CPU when it has them. Each function runs over 2^20 arguments from
// the ranges btFracture uses (angles, cosines, positive scales); the best of 7 passes counts.
//
// Prints METRIC pmath_<f>_ns and std_<f>_ns (nanoseconds per call) for every function.
#include "BestOf.h"

#include <btFracture/core/PortableMath.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace btfracture;

namespace {

constexpr int kPoints = 1 << 20;

// Evenly spread over [lo, hi], or logarithmically for `logarithmic`.
std::vector<double> arguments(double lo, double hi, bool logarithmic = false) {
    std::vector<double> xs(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        const double t = (i + 0.5) / kPoints;
        xs[i] = logarithmic ? lo * pmath::pow(hi / lo, t) : lo + t * (hi - lo);
    }
    return xs;
}

volatile double sink;

template <class F>
double nanosecondsPerCall(F f, const std::vector<double>& xs) {
    const double seconds = bestOf(7, [&] {
        double sum = 0.0;
        for (double x : xs) sum += f(x);
        sink = sum;
    });
    return 1e9 * seconds / xs.size();
}

template <class P, class S>
void compare(const char* name, P portable, S system, const std::vector<double>& xs) {
    std::printf("METRIC pmath_%s_ns %.1f ns\n", name, nanosecondsPerCall(portable, xs));
    std::printf("METRIC std_%s_ns %.1f ns\n", name, nanosecondsPerCall(system, xs));
}

}  // namespace

int main() {
    const std::vector<double> angles = arguments(-2.0 * M_PI, 2.0 * M_PI);
    const std::vector<double> halfAngles = arguments(-1.5, 1.5);
    const std::vector<double> cosines = arguments(-1.0, 1.0);
    const std::vector<double> ratios = arguments(-50.0, 50.0);
    const std::vector<double> exponents = arguments(-20.0, 5.0);
    const std::vector<double> scales = arguments(1e-9, 1e12, true);

    compare(
        "sin", [](double x) { return pmath::sin(x); }, [](double x) { return std::sin(x); }, angles);
    compare(
        "cos", [](double x) { return pmath::cos(x); }, [](double x) { return std::cos(x); }, angles);
    compare(
        "tan", [](double x) { return pmath::tan(x); }, [](double x) { return std::tan(x); }, halfAngles);
    compare(
        "asin", [](double x) { return pmath::asin(x); }, [](double x) { return std::asin(x); }, cosines);
    compare(
        "acos", [](double x) { return pmath::acos(x); }, [](double x) { return std::acos(x); }, cosines);
    compare(
        "atan", [](double x) { return pmath::atan(x); }, [](double x) { return std::atan(x); }, ratios);
    compare(
        "atan2", [](double x) { return pmath::atan2(x, 0.7); }, [](double x) { return std::atan2(x, 0.7); },
        ratios);
    compare(
        "exp", [](double x) { return pmath::exp(x); }, [](double x) { return std::exp(x); }, exponents);
    compare(
        "log", [](double x) { return pmath::log(x); }, [](double x) { return std::log(x); }, scales);
    compare(
        "log10", [](double x) { return pmath::log10(x); }, [](double x) { return std::log10(x); }, scales);
    compare(
        "pow", [](double x) { return pmath::pow(x, 0.6); }, [](double x) { return std::pow(x, 0.6); },
        scales);
    return 0;
}
