// SPDX-License-Identifier: Zlib
#pragma once
// Sauter-Schwab quadrature for singular pairs of flat triangles.
#include <btFracture/bem/Quadrature.h>

#include <array>
#include <vector>

namespace btfracture {

enum class PairRelation { Identical, CommonEdge, CommonVertex, Separated };

// Sauter & Schwab (2011, Sec. 5.2.1) regularising maps on the reference triangle
// {0 <= x2 <= x1 <= 1}, point = A + x1 (B - A) + x2 (C - B). The singular set (coincident
// points, the common edge A-B, the common vertex A) is pulled onto faces of [0,1]^4 where the
// Jacobian vanishes fast enough to cancel 1/r. Calls visit(x1, x2, y1, y2, weight); the
// weights integrate 1 over the reference pair to 1/4.
template <class Visit>
void forEachSauterSchwabPoint(PairRelation relation, int n, Visit&& visit) {
    const LineRule& g = gaussLegendre(n);
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
            for (int c = 0; c < n; ++c)
                for (int d = 0; d < n; ++d) {
                    const double xi = g.points[a], e1 = g.points[b], e2 = g.points[c], e3 = g.points[d];
                    const double w = g.weights[a] * g.weights[b] * g.weights[c] * g.weights[d];
                    const double xi3 = xi * xi * xi;
                    switch (relation) {
                        case PairRelation::Identical: {
                            const double wj = w * xi3 * e1 * e1 * e2;
                            const double p1 = xi, p2 = xi * (1 - e1 + e1 * e2);
                            const double q1 = xi * (1 - e1 * e2 * e3), q2 = xi * (1 - e1);
                            visit(p1, p2, q1, q2, wj);
                            visit(q1, q2, p1, p2, wj);
                            const double r1 = xi, r2 = xi * e1 * (1 - e2 + e2 * e3);
                            const double s1 = xi * (1 - e1 * e2), s2 = xi * e1 * (1 - e2);
                            visit(r1, r2, s1, s2, wj);
                            visit(s1, s2, r1, r2, wj);
                            const double t1 = xi * (1 - e1 * e2 * e3), t2 = xi * e1 * (1 - e2 * e3);
                            const double u1 = xi, u2 = xi * e1 * (1 - e2);
                            visit(t1, t2, u1, u2, wj);
                            visit(u1, u2, t1, t2, wj);
                            break;
                        }
                        case PairRelation::CommonEdge: {
                            const double w1 = w * xi3 * e1 * e1;
                            const double w2 = w1 * e2;
                            visit(xi, xi * e1 * e3, xi * (1 - e1 * e2), xi * e1 * (1 - e2), w1);
                            visit(xi, xi * e1, xi * (1 - e1 * e2 * e3), xi * e1 * e2 * (1 - e3), w2);
                            visit(xi * (1 - e1 * e2), xi * e1 * (1 - e2), xi, xi * e1 * e2 * e3, w2);
                            visit(xi * (1 - e1 * e2 * e3), xi * e1 * e2 * (1 - e3), xi, xi * e1, w2);
                            visit(xi * (1 - e1 * e2 * e3), xi * e1 * (1 - e2 * e3), xi, xi * e1 * e2, w2);
                            break;
                        }
                        case PairRelation::CommonVertex: {
                            const double wj = w * xi3 * e2;
                            visit(xi, xi * e1, xi * e2, xi * e2 * e3, wj);
                            visit(xi * e2, xi * e2 * e3, xi, xi * e1, wj);
                            break;
                        }
                        case PairRelation::Separated:
                            break;
                    }
                }
}

// The same points, tabulated once per (relation, n) for 1 <= n <= 12 at its first use (thread
// safe): x1, x2, y1, y2, weight.
// With `swapSymmetric` the identical-panel rule merges each point pair with its x <-> y swap
// (half the points), valid only for integrands symmetric under that swap.
struct SauterSchwabRule {
    std::vector<std::array<double, 5>> points;
};
const SauterSchwabRule& sauterSchwabRule(PairRelation relation, int n, bool swapSymmetric = false);

}  // namespace btfracture
