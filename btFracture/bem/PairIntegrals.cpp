#include <btFracture/bem/PairIntegrals.h>

#include <btFracture/bem/Quadrature.h>
#include <btFracture/bem/SauterSchwab.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

constexpr double kInvFourPi = 0.25 / M_PI;

// Accumulates the kernels of PairIntegrals at one point pair; phiX / phiY are the P1 hat values
// at x and y in the panels' own corner order.
struct Accumulator {
    const Eigen::Vector3d& normalX;
    const Eigen::Vector3d& normalY;
    bool doubleLayer;  // false for coplanar pairs, where (x - y).n vanishes identically
    PairIntegrals sum;

    void add(const double* x, const double* y, const double* phiX, const double* phiY, double w) {
        const double r0 = x[0] - y[0], r1 = x[1] - y[1], r2 = x[2] - y[2];
        const double invR = 1.0 / std::sqrt(r0 * r0 + r1 * r1 + r2 * r2);
        const double wInvR = w * invR;
        const double wInvR3 = wInvR * invR * invR;
        sum.inverseDistance += wInvR;
        const double s0 = wInvR3 * r0, s1 = wInvR3 * r1, s2 = wInvR3 * r2;
        dyadic[0] += s0 * r0;
        dyadic[1] += s0 * r1;
        dyadic[2] += s0 * r2;
        dyadic[3] += s1 * r1;
        dyadic[4] += s1 * r2;
        dyadic[5] += s2 * r2;
        if (doubleLayer) {
            const double kXY = kInvFourPi * (s0 * normalY[0] + s1 * normalY[1] + s2 * normalY[2]);
            const double kYX = -kInvFourPi * (s0 * normalX[0] + s1 * normalX[1] + s2 * normalX[2]);
            for (int k = 0; k < 3; ++k) {
                sum.doubleLayerXY[k] += kXY * phiY[k];
                sum.doubleLayerYX[k] += kYX * phiX[k];
            }
        }
    }

    PairIntegrals result() {
        sum.dyadic << dyadic[0], dyadic[1], dyadic[2], dyadic[1], dyadic[3], dyadic[4], dyadic[2], dyadic[4],
            dyadic[5];
        return sum;
    }

    double dyadic[6] = {0, 0, 0, 0, 0, 0};
};

double diameterOf(const Panel& p) {
    return std::max({(p.corners[1] - p.corners[0]).norm(), (p.corners[2] - p.corners[1]).norm(),
                     (p.corners[0] - p.corners[2]).norm()});
}

Eigen::Vector3d centroidOf(const Panel& p) {
    return (p.corners[0] + p.corners[1] + p.corners[2]) / 3.0;
}

bool coplanar(const Panel& x, const Panel& y) {
    const double scale = std::max(diameterOf(x), diameterOf(y));
    for (const auto& c : y.corners)
        if (std::abs((c - x.corners[0]).dot(x.normal)) > 1e-12 * scale) return false;
    return std::abs(x.normal.dot(y.normal)) > 1.0 - 1e-14;
}

}  // namespace

int separatedRuleLevel(double eta, const QuadratureSettings& s) {
    return eta < s.nearRatio ? 0 : eta < s.midRatio ? 1 : eta < s.farRatio ? 2 : 3;
}

int separatedRuleDegree(double eta, const QuadratureSettings& s) {
    const std::array<int, 4> degrees{s.nearDegree, s.midDegree, s.farDegree, s.veryFarDegree};
    return degrees[separatedRuleLevel(eta, s)];
}

PanelPoints::PanelPoints(const Panel& panel, int degree) {
    const TriangleRule& rule = triangleRule(degree);
    count = static_cast<int>(rule.points.size());
    data.resize(kStride * count);
    for (int i = 0; i < count; ++i) {
        const auto& p = rule.points[i];
        const Eigen::Vector3d x = p.l0 * panel.corners[0] + p.l1 * panel.corners[1] + p.l2 * panel.corners[2];
        double* d = &data[kStride * i];
        d[0] = x.x(), d[1] = x.y(), d[2] = x.z();
        d[3] = p.l0, d[4] = p.l1, d[5] = p.l2;
        d[6] = p.w * panel.area;
    }
}

PairIntegrals integrateSeparated(const Panel& x, const PanelPoints& px, const Panel& y, const PanelPoints& py,
                                 bool doubleLayer) {
    Accumulator acc{x.normal, y.normal, doubleLayer, {}};
    for (int i = 0; i < px.count; ++i) {
        const double* a = &px.data[PanelPoints::kStride * i];
        for (int j = 0; j < py.count; ++j) {
            const double* b = &py.data[PanelPoints::kStride * j];
            acc.add(a, b, a + 3, b + 3, a[6] * b[6]);
        }
    }
    return acc.result();
}

namespace {

// Reorders the corners of x and y so that shared corners come first, in the same order in both
// (edge A-B or vertex A); permX[k] / permY[k] give the original corner of reordered corner k.
void alignShared(const Panel& x, const Panel& y, std::array<int, 3>& permX, std::array<int, 3>& permY) {
    int nShared = 0;
    std::array<int, 3> sharedX{}, sharedY{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (x.ids[i] == y.ids[j]) {
                sharedX[nShared] = i;
                sharedY[nShared] = j;
                ++nShared;
            }
    auto complete = [](std::array<int, 3>& perm, const std::array<int, 3>& shared, int nShared) {
        for (int k = 0; k < nShared; ++k) perm[k] = shared[k];
        int next = nShared;
        for (int i = 0; i < 3; ++i)
            if (std::find(perm.begin(), perm.begin() + nShared, i) == perm.begin() + nShared)
                perm[next++] = i;
    };
    complete(permX, sharedX, nShared);
    complete(permY, sharedY, nShared);
}

void integrateSingular(const Panel& x, const Panel& y, PairRelation relation, int n, Accumulator& acc) {
    std::array<int, 3> permX{0, 1, 2}, permY{0, 1, 2};
    if (relation != PairRelation::Identical) alignShared(x, y, permX, permY);
    const Eigen::Vector3d& xa = x.corners[permX[0]];
    const Eigen::Vector3d xab = x.corners[permX[1]] - xa, xbc = x.corners[permX[2]] - x.corners[permX[1]];
    const Eigen::Vector3d& ya = y.corners[permY[0]];
    const Eigen::Vector3d yab = y.corners[permY[1]] - ya, ybc = y.corners[permY[2]] - y.corners[permY[1]];
    const double jacobian = 4.0 * x.area * y.area;
    // Identical panels: the double layer vanishes, the other kernels are even in x - y.
    const SauterSchwabRule& rule = sauterSchwabRule(relation, n, relation == PairRelation::Identical);
    for (const auto& [x1, x2, y1, y2, w] : rule.points) {
        double phiX[3], phiY[3], xp[3], yp[3];
        phiX[permX[0]] = 1.0 - x1;
        phiX[permX[1]] = x1 - x2;
        phiX[permX[2]] = x2;
        phiY[permY[0]] = 1.0 - y1;
        phiY[permY[1]] = y1 - y2;
        phiY[permY[2]] = y2;
        for (int k = 0; k < 3; ++k) {
            xp[k] = xa[k] + x1 * xab[k] + x2 * xbc[k];
            yp[k] = ya[k] + y1 * yab[k] + y2 * ybc[k];
        }
        acc.add(xp, yp, phiX, phiY, jacobian * w);
    }
}

}  // namespace

PairRelation relationOf(const Panel& x, const Panel& y) {
    int shared = 0;
    for (int i : x.ids)
        for (int j : y.ids) shared += (i == j);
    switch (shared) {
        case 0:
            return PairRelation::Separated;
        case 1:
            return PairRelation::CommonVertex;
        case 2:
            return PairRelation::CommonEdge;
        default:
            return PairRelation::Identical;
    }
}

PairIntegrals integrateSingular(const Panel& x, const Panel& y, const QuadratureSettings& settings) {
    const PairRelation relation = relationOf(x, y);
    const bool doubleLayer = relation != PairRelation::Identical && !coplanar(x, y);
    Accumulator acc{x.normal, y.normal, doubleLayer, {}};
    integrateSingular(x, y, relation,
                      relation == PairRelation::Identical    ? settings.identicalPoints
                      : relation == PairRelation::CommonEdge ? settings.edgePoints
                                                             : settings.vertexPoints,
                      acc);
    return acc.result();
}

QuadraturePanel::QuadraturePanel(const Panel& p, const QuadratureSettings& s)
    : panel(p), centroid(centroidOf(p)), diameter(diameterOf(p)) {
    const std::array<int, 4> degrees{s.nearDegree, s.midDegree, s.farDegree, s.veryFarDegree};
    for (int level = 0; level < 4; ++level) points[level] = PanelPoints(p, degrees[level]);
}

PairIntegrals integratePair(const Panel& x, const Panel& y, const QuadratureSettings& settings) {
    if (relationOf(x, y) != PairRelation::Separated) return integrateSingular(x, y, settings);
    const int degree = separatedRuleDegree(
        (centroidOf(x) - centroidOf(y)).norm() / std::max(diameterOf(x), diameterOf(y)), settings);
    return integrateSeparated(x, PanelPoints(x, degree), y, PanelPoints(y, degree));
}

PairIntegrals integrateSeparated(const QuadraturePanel& x, const QuadraturePanel& y,
                                 const QuadratureSettings& settings, bool doubleLayer) {
    const int level =
        separatedRuleLevel((x.centroid - y.centroid).norm() / std::max(x.diameter, y.diameter), settings);
    return integrateSeparated(x.panel, x.points[level], y.panel, y.points[level], doubleLayer);
}

PairIntegrals integratePair(const QuadraturePanel& x, const QuadraturePanel& y,
                            const QuadratureSettings& settings) {
    if (relationOf(x.panel, y.panel) != PairRelation::Separated)
        return integrateSingular(x.panel, y.panel, settings);
    return integrateSeparated(x, y, settings);
}

}  // namespace btfracture
