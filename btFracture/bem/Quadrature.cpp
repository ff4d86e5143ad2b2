// SPDX-License-Identifier: Zlib
#include <btFracture/bem/Quadrature.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <array>
#include <cmath>
#include <string>

namespace btfracture {
namespace {

constexpr int kMaxLinePoints = 40;
constexpr int kMaxTriangleDegree = 30;

LineRule makeGaussLegendre(int n) {
    // Newton iteration on the Legendre polynomial P_n from Chebyshev-like initial guesses.
    LineRule rule;
    rule.points.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < n; ++i) {
        double x = pmath::cos(M_PI * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0);  // P_n' from P_n = p1, P_{n-1} = p0
            const double step = p1 / dp;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        // Map from [-1, 1] to [0, 1].
        rule.points[n - 1 - i] = 0.5 * (x + 1.0);
        rule.weights[n - 1 - i] = 1.0 / ((1.0 - x * x) * dp * dp);
    }
    return rule;
}

void addOrbit3(TriangleRule& rule, double a, double w) {  // (a, b, b) and permutations, b = (1 - a) / 2
    const double b = 0.5 * (1.0 - a);
    rule.points.push_back({a, b, b, w});
    rule.points.push_back({b, a, b, w});
    rule.points.push_back({b, b, a, w});
}

// (a, b, c) and its five other permutations, c = 1 - a - b.
void addOrbit6(TriangleRule& rule, double a, double b, double w) {
    const double c = 1.0 - a - b;
    rule.points.push_back({a, b, c, w});
    rule.points.push_back({a, c, b, w});
    rule.points.push_back({b, a, c, w});
    rule.points.push_back({b, c, a, w});
    rule.points.push_back({c, a, b, w});
    rule.points.push_back({c, b, a, w});
}

TriangleRule makeTriangleRule(int degree) {
    TriangleRule rule;
    if (degree <= 1) {
        rule.points.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0});
        rule.degree = 1;
    } else if (degree == 2) {
        addOrbit3(rule, 2.0 / 3.0, 1.0 / 3.0);
        rule.degree = 2;
    } else if (degree <= 4) {  // Dunavant's 6-point rule
        addOrbit3(rule, 0.108103018168070, 0.223381589678011);
        addOrbit3(rule, 0.816847572980459, 0.109951743655322);
        rule.degree = 4;
    } else if (degree == 5) {  // Radon's 7-point rule
        rule.points.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225});
        addOrbit3(rule, 0.059715871789770, 0.132394152788506);
        addOrbit3(rule, 0.797426985353087, 0.125939180544827);
        rule.degree = 5;
    } else if (degree == 6) {  // Dunavant's 12-point rule
        addOrbit3(rule, 0.501426509658179, 0.116786275726379);
        addOrbit3(rule, 0.873821971016996, 0.050844906370207);
        addOrbit6(rule, 0.053145049844817, 0.310352451033784, 0.082851075618374);
        rule.degree = 6;
    } else if (degree <= 8) {  // Dunavant's 16-point rule
        rule.points.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3, 0.144315607677787});
        addOrbit3(rule, 0.081414823414554, 0.095091634267285);
        addOrbit3(rule, 0.658861384496480, 0.103217370534718);
        addOrbit3(rule, 0.898905543365938, 0.032458497623198);
        addOrbit6(rule, 0.008394777409958, 0.263112829634638, 0.027230314174435);
        rule.degree = 8;
    } else {
        // Conical product: x1 = u, x2 = u v on {0 <= x2 <= x1 <= 1}, Jacobian u; n points per
        // direction integrate degree 2n - 2 in (x1, x2) exactly (the Jacobian adds one in u).
        const int n = (degree + 3) / 2;
        const LineRule& g = gaussLegendre(n);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double u = g.points[i], v = g.points[j];
                rule.points.push_back({1.0 - u, u - u * v, u * v, 2.0 * g.weights[i] * g.weights[j] * u});
            }
        rule.degree = 2 * n - 2;
    }
    return rule;
}

}  // namespace

const LineRule& gaussLegendre(int n) {
    if (n < 1 || n > kMaxLinePoints)
        throw Error("Gauss-Legendre rule with " + std::to_string(n) + " points requested; supported: 1.." +
                    std::to_string(kMaxLinePoints));
    static const std::array<LineRule, kMaxLinePoints + 1> rules = [] {
        std::array<LineRule, kMaxLinePoints + 1> all;
        for (int k = 1; k <= kMaxLinePoints; ++k) all[k] = makeGaussLegendre(k);
        return all;
    }();
    return rules[n];
}

const TriangleRule& triangleRule(int degree) {
    if (degree < 1 || degree > kMaxTriangleDegree)
        throw Error("triangle quadrature of degree " + std::to_string(degree) + " requested; supported: 1.." +
                    std::to_string(kMaxTriangleDegree));
    static const std::array<TriangleRule, kMaxTriangleDegree + 1> rules = [] {
        std::array<TriangleRule, kMaxTriangleDegree + 1> all;
        for (int d = 1; d <= kMaxTriangleDegree; ++d) all[d] = makeTriangleRule(d);
        return all;
    }();
    return rules[degree];
}

}  // namespace btfracture
