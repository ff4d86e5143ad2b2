// SPDX-License-Identifier: Zlib
// Quadrature: line and triangle rules are exact on polynomials, the Sauter-Schwab maps tile the
// reference pair exactly, and singular 1/r integrals match a semi-analytic evaluation.
#include <btFracture/bem/PairIntegrals.h>
#include <btFracture/bem/Quadrature.h>
#include <btFracture/bem/SauterSchwab.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace btfracture;

namespace {

Panel panel(std::array<int, 3> ids, Eigen::Vector3d a, Eigen::Vector3d b, Eigen::Vector3d c) {
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    return Panel{ids, {a, b, c}, cross.normalized(), 0.5 * cross.norm()};
}

// int over panel p of 1/|x - y| dy for x in p's plane: sum over edges of
// d_e ln((l+ + s+) / (l- + s-)), d_e the distance from x to the edge line (positive inside),
// s the arc coordinates of the edge ends from the foot point, l the distances to the ends.
double inverseDistancePotential(const Eigen::Vector3d& x, const Panel& p) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& a = p.corners[k];
        const Eigen::Vector3d& b = p.corners[(k + 1) % 3];
        const Eigen::Vector3d t = (b - a).normalized();
        const double d = (a - x).dot(t.cross(p.normal));
        if (std::abs(d) < 1e-14) continue;
        const double sMinus = (a - x).dot(t), sPlus = (b - x).dot(t);
        sum += d * std::log(((b - x).norm() + sPlus) / ((a - x).norm() + sMinus));
    }
    return sum;
}

// int_x int_y 1/r for two coplanar panels: the analytic inner potential integrated over x on
// a 4^k-fold subdivision of x with a high-degree rule (converges algebraically near the
// singular set, to about 1e-9 here).
double coplanarReference(const Panel& x, const Panel& y) {
    const int levels = 16;
    const TriangleRule& rule = triangleRule(16);
    double sum = 0.0;
    auto point = [&](double u, double v) {
        return x.corners[0] + (u / levels) * (x.corners[1] - x.corners[0]) +
               (v / levels) * (x.corners[2] - x.corners[0]);
    };
    for (int i = 0; i < levels; ++i)
        for (int j = 0; i + j < levels; ++j)
            for (int up = 0; up < 2; ++up) {
                if (up && i + j == levels - 1) continue;
                const Eigen::Vector3d a = up ? point(i + 1, j) : point(i, j);
                const Eigen::Vector3d b = up ? point(i + 1, j + 1) : point(i + 1, j);
                const Eigen::Vector3d c = up ? point(i, j + 1) : point(i, j + 1);
                for (const auto& q : rule.points)
                    sum += x.area / (levels * levels) * q.w *
                           inverseDistancePotential(q.l0 * a + q.l1 * b + q.l2 * c, y);
            }
    return sum;
}

// int over the reference triangle {0 <= x2 <= x1 <= 1} of x1^a x2^b.
double referenceMonomial(int a, int b) {
    return 1.0 / ((b + 1.0) * (a + b + 2.0));
}

}  // namespace

TEST(Quadrature, GaussLegendreIntegratesPolynomialsExactly) {
    for (int n = 1; n <= 12; ++n) {
        const LineRule& g = gaussLegendre(n);
        for (int p = 0; p <= 2 * n - 1; ++p) {
            double sum = 0.0;
            for (int i = 0; i < n; ++i) sum += g.weights[i] * std::pow(g.points[i], p);
            EXPECT_NEAR(sum, 1.0 / (p + 1), 1e-14) << "n = " << n << ", degree " << p;
        }
    }
}

TEST(Quadrature, TriangleRulesIntegrateMonomialsExactly) {
    // Unit weight sum: int of l1^a l2^b over the triangle / area = 2 a! b! / (a + b + 2)!.
    auto factorial = [](int k) { return std::tgamma(k + 1.0); };
    for (int degree : {1, 2, 3, 4, 5, 6, 7, 8, 12, 20}) {
        const TriangleRule& rule = triangleRule(degree);
        EXPECT_GE(rule.degree, degree);
        for (int a = 0; a <= degree; ++a)
            for (int b = 0; a + b <= degree; ++b) {
                double sum = 0.0;
                for (const auto& p : rule.points) sum += p.w * std::pow(p.l1, a) * std::pow(p.l2, b);
                EXPECT_NEAR(sum, 2.0 * factorial(a) * factorial(b) / factorial(a + b + 2), 1e-13)
                    << "degree " << degree << ", monomial " << a << " " << b;
            }
    }
}

TEST(Quadrature, SauterSchwabMapsTileTheReferencePair) {
    // Products of monomials in x and y are smooth, so the transformed rule integrates them
    // exactly once the Gauss order covers their degree; a wrong map fails this at once.
    for (PairRelation relation :
         {PairRelation::Identical, PairRelation::CommonEdge, PairRelation::CommonVertex})
        for (int a = 0; a <= 2; ++a)
            for (int b = 0; b <= 2; ++b)
                for (int c = 0; c <= 1; ++c)
                    for (int d = 0; d <= 2; ++d) {
                        double sum = 0.0;
                        forEachSauterSchwabPoint(
                            relation, 6, [&](double x1, double x2, double y1, double y2, double w) {
                                sum +=
                                    w * std::pow(x1, a) * std::pow(x2, b) * std::pow(y1, c) * std::pow(y2, d);
                            });
                        EXPECT_NEAR(sum, referenceMonomial(a, b) * referenceMonomial(c, d), 1e-14)
                            << "relation " << static_cast<int>(relation) << " monomial " << a << b << c << d;
                    }
}

TEST(Quadrature, SingularPairsMatchSemiAnalyticReference) {
    const Eigen::Vector3d a(0.1, 0.2, 0), b(1.3, 0.4, 0), c(0.5, 1.1, 0), d(0.9, -0.6, 0), e(-0.5, -0.2, 0);
    const Panel x = panel({0, 1, 2}, a, b, c);
    const Panel edge = panel({1, 0, 3}, b, a, d);
    const Panel vertex = panel({0, 3, 4}, a, d, e);
    QuadratureSettings settings;  // production order
    for (const Panel* y : {&x, &edge, &vertex}) {
        const double value = integratePair(x, *y, settings).inverseDistance;
        const double reference = coplanarReference(x, *y);
        EXPECT_NEAR(value / reference, 1.0, 1e-6) << "relation " << static_cast<int>(relationOf(x, *y));
    }
}

TEST(Quadrature, NonCoplanarSingularPairsConverge) {
    // Relative change from the production order to a much higher one (the production orders are
    // chosen for ~1e-7 on 1/r and ~1e-5 on the dyadic and double-layer kernels).
    const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.4, 0.8, 0.1), d(0.5, -0.7, 0.4), e(-0.6, -0.3, 0.5);
    const Panel x = panel({0, 1, 2}, a, b, c);
    const Panel edge = panel({1, 0, 3}, b, a, d);
    const Panel vertex = panel({0, 3, 4}, a, d, e);
    QuadratureSettings production, fine;
    fine.identicalPoints = fine.edgePoints = fine.vertexPoints = 12;
    for (const Panel* y : {&x, &edge, &vertex}) {
        const PairIntegrals p = integratePair(x, *y, production), f = integratePair(x, *y, fine);
        EXPECT_NEAR(p.inverseDistance / f.inverseDistance, 1.0, 1e-6);
        EXPECT_LT((p.dyadic - f.dyadic).norm() / f.dyadic.norm(), 1e-5);
        EXPECT_LT((p.doubleLayerXY - f.doubleLayerXY).norm(), 2e-5 * f.doubleLayerXY.norm() + 1e-12);
        EXPECT_LT((p.doubleLayerYX - f.doubleLayerYX).norm(), 2e-5 * f.doubleLayerYX.norm() + 1e-12);
    }
}

TEST(Quadrature, SeparatedPairsAreSymmetricAndConverge) {
    const Panel x = panel({0, 1, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const Panel y = panel({3, 4, 5}, {0.3, 0.2, 1.5}, {1.4, 0.5, 1.2}, {0.2, 1.1, 1.8});
    QuadratureSettings production, fine;
    fine.levelDegrees.fill(20);
    const PairIntegrals p = integratePair(x, y, production), f = integratePair(x, y, fine);
    EXPECT_NEAR(p.inverseDistance / f.inverseDistance, 1.0, 1e-6);
    const PairIntegrals swapped = integratePair(y, x, production);
    EXPECT_NEAR(swapped.inverseDistance, p.inverseDistance, 1e-14 * p.inverseDistance);
    EXPECT_LT((swapped.doubleLayerXY - p.doubleLayerYX).norm(), 1e-14);
}

TEST(Quadrature, NearlyTouchingPairsConverge) {
    // A crack element whose corner lies about 1 % of its size above the interior of a surface
    // triangle (eta 0.14): the production rules with subdivision (64 sub-pairs) agree with a much
    // finer reference to 1e-4 (1/r, r r^T / r^3) and 3e-3 (double layers), while one degree-8
    // rule on the whole pair is off by 3 % on 1/r, 18 % on r r^T / r^3 and 64 % on a double layer.
    const Panel surface = panel({0, 1, 2}, {-1, -1, 0}, {2, -1, 0}, {-1, 2, 0});
    const Panel crack = panel({3, 4, 5}, {0.2, 0.1, 0.01}, {0.7, 0.2, 0.5}, {0.1, 0.6, 0.6});
    QuadratureSettings production, fine, single;
    fine.subdivisionRatio = fine.subPairRatio = 4.0;
    fine.maxSubPairs = 4096;
    fine.levelDegrees.fill(8);
    single.subdivisionRatio = 0.0;
    const PairIntegrals p = integratePair(surface, crack, production),
                        f = integratePair(surface, crack, fine), s = integratePair(surface, crack, single);
    EXPECT_NEAR(p.inverseDistance / f.inverseDistance, 1.0, 1e-4);
    EXPECT_LT((p.dyadic - f.dyadic).norm(), 1e-4 * f.dyadic.norm());
    EXPECT_LT((p.doubleLayerXY - f.doubleLayerXY).norm(), 3e-3 * f.doubleLayerXY.norm());
    EXPECT_LT((p.doubleLayerYX - f.doubleLayerYX).norm(), 3e-3 * f.doubleLayerYX.norm());
    EXPECT_GT((s.dyadic - f.dyadic).norm(), 1e-2 * f.dyadic.norm());
}

TEST(Quadrature, SeparatedPairSumsMatchAPlainDoubleLoop) {
    // The separated-pair kernel sums per lane of y points (chunks of 32) and skips the double
    // layer on request; a plain double loop over the same rule is the reference, for rules of 3,
    // 6, 16 and 121 points (the last spans four chunks).
    const Panel x = panel({0, 1, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const Panel y = panel({3, 4, 5}, {0.3, 0.2, 1.5}, {1.4, 0.5, 1.2}, {0.2, 1.1, 1.8});
    for (int degree : {2, 4, 8, 20}) {
        const TriangleRule& rule = triangleRule(degree);
        double inverse = 0.0;
        Eigen::Matrix3d dyadic = Eigen::Matrix3d::Zero();
        Eigen::Vector3d layerXY = Eigen::Vector3d::Zero(), layerYX = Eigen::Vector3d::Zero();
        for (const auto& p : rule.points)
            for (const auto& q : rule.points) {
                const Eigen::Vector3d px = p.l0 * x.corners[0] + p.l1 * x.corners[1] + p.l2 * x.corners[2];
                const Eigen::Vector3d qy = q.l0 * y.corners[0] + q.l1 * y.corners[1] + q.l2 * y.corners[2];
                const Eigen::Vector3d r = px - qy;
                const double w = p.w * x.area * q.w * y.area, len = r.norm();
                inverse += w / len;
                dyadic += w * r * r.transpose() / (len * len * len);
                const Eigen::Vector3d hatX(p.l0, p.l1, p.l2), hatY(q.l0, q.l1, q.l2);
                layerXY += w * r.dot(y.normal) / (4 * M_PI * len * len * len) * hatY;
                layerYX -= w * r.dot(x.normal) / (4 * M_PI * len * len * len) * hatX;
            }
        const PanelPoints px(x, degree), py(y, degree);
        const PairIntegrals all = integrateSeparated(x, px, y, py),
                            single = integrateSeparated(x, px, y, py, false);
        EXPECT_NEAR(all.inverseDistance / inverse, 1.0, 1e-13) << "degree " << degree;
        EXPECT_LT((all.dyadic - dyadic).norm(), 1e-13 * dyadic.norm()) << "degree " << degree;
        EXPECT_LT((all.doubleLayerXY - layerXY).norm(), 1e-13 * layerXY.norm()) << "degree " << degree;
        EXPECT_LT((all.doubleLayerYX - layerYX).norm(), 1e-13 * layerYX.norm()) << "degree " << degree;
        EXPECT_EQ(single.inverseDistance, all.inverseDistance);
        EXPECT_EQ(single.dyadic, all.dyadic);
        EXPECT_EQ(single.doubleLayerXY, Eigen::Vector3d::Zero());
        EXPECT_EQ(single.doubleLayerYX, Eigen::Vector3d::Zero());
    }
}

TEST(Quadrature, PrecomputedPanelsGiveThePlainPairs) {
    // QuadraturePanel only caches what integratePair(Panel, Panel) computes per call: same rule
    // level at every distance, same numbers; shared nodes still go to Sauter-Schwab.
    QuadratureSettings settings;
    const Panel x = panel({0, 1, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const QuadraturePanel qx(x, settings);
    for (double height : {0.5, 2.0, 4.0, 8.0}) {  // near, mid, far and very far rules
        const Panel y =
            panel({3, 4, 5}, {0.3, 0.2, height}, {1.4, 0.5, height - 0.3}, {0.2, 1.1, height + 0.2});
        const PairIntegrals plain = integratePair(x, y, settings),
                            cached = integratePair(qx, QuadraturePanel(y, settings), settings);
        EXPECT_EQ(cached.inverseDistance, plain.inverseDistance) << "height " << height;
        EXPECT_EQ(cached.dyadic, plain.dyadic) << "height " << height;
        EXPECT_EQ(cached.doubleLayerXY, plain.doubleLayerXY) << "height " << height;
    }
    const Panel edge = panel({1, 0, 3}, {1, 0, 0}, {0, 0, 0}, {0.5, -0.7, 0.4});
    EXPECT_EQ(integratePair(qx, QuadraturePanel(edge, settings), settings).inverseDistance,
              integratePair(x, edge, settings).inverseDistance);
}
