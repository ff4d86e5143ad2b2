// SPDX-License-Identifier: Zlib
#include <btFracture/bem/PairIntegrals.h>

#include <btFracture/bem/Quadrature.h>
#include <btFracture/bem/SauterSchwab.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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

using Corners = std::array<Eigen::Vector3d, 3>;

double diameterOf(const Corners& c) {
    return std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
}

Eigen::Vector3d centroidOf(const Corners& c) {
    return (c[0] + c[1] + c[2]) / 3.0;
}

// Centroid distance over the larger diameter: the ratio that picks a separated pair's rule.
double separationRatio(const Eigen::Vector3d& centroidX, double diameterX, const Eigen::Vector3d& centroidY,
                       double diameterY) {
    return (centroidX - centroidY).norm() / std::max(diameterX, diameterY);
}

bool coplanar(const Panel& x, const Panel& y) {
    const double scale = std::max(diameterOf(x.corners), diameterOf(y.corners));
    for (const auto& c : y.corners)
        if (std::abs((c - x.corners[0]).dot(x.normal)) > 1e-12 * scale) return false;
    return std::abs(x.normal.dot(y.normal)) > 1.0 - 1e-14;
}

}  // namespace

int separatedRuleLevel(double eta, const QuadratureSettings& s) {
    int level = 0;
    while (level < QuadratureSettings::kSeparatedLevels - 1 && eta >= s.levelRatios[level]) ++level;
    return level;
}

int separatedRuleDegree(double eta, const QuadratureSettings& s) {
    return s.levelDegrees[separatedRuleLevel(eta, s)];
}

PanelPoints::PanelPoints(const Panel& panel, int degree) {
    const TriangleRule& rule = triangleRule(degree);
    count = static_cast<int>(rule.points.size());
    data.resize(kFields * count);
    for (int i = 0; i < count; ++i) {
        const auto& p = rule.points[i];
        const Eigen::Vector3d x = p.l0 * panel.corners[0] + p.l1 * panel.corners[1] + p.l2 * panel.corners[2];
        const double fields[kFields] = {x.x(), x.y(), x.z(), p.l0, p.l1, p.l2, p.w * panel.area};
        for (int f = 0; f < kFields; ++f) data[f * count + i] = fields[f];
    }
}

namespace {

// The separated-pair sums, vectorised over the points of y: each lane j keeps its own partial
// sums over the points of x (no reduction across lanes inside the loop), summed in a fixed
// order at the end. 13 sums: 1/r, the six entries of r r^T / r^3, the two double layers.
template <bool kDoubleLayer>
PairIntegrals separatedSums(const Panel& x, const PanelPoints& px, const Panel& y, const PanelPoints& py) {
    constexpr int kLanes = 32;  // y points per chunk (every production rule fits one chunk)
    constexpr int kSums = 13;
    double total[kSums] = {};
    const int nx = px.count, ny = py.count;
    const double* X[PanelPoints::kFields];
    const double* Y[PanelPoints::kFields];
    for (int f = 0; f < PanelPoints::kFields; ++f) {
        X[f] = &px.data[f * nx];
        Y[f] = &py.data[f * ny];
    }
    const double nx0 = x.normal[0], nx1 = x.normal[1], nx2 = x.normal[2];
    const double ny0 = y.normal[0] * kInvFourPi, ny1 = y.normal[1] * kInvFourPi,
                 ny2 = y.normal[2] * kInvFourPi;
    for (int j0 = 0; j0 < ny; j0 += kLanes) {
        const int lanes = std::min(kLanes, ny - j0);
        alignas(64) double lane[kSums][kLanes];
        for (auto& row : lane) std::fill(row, row + lanes, 0.0);
        for (int i = 0; i < nx; ++i) {
            const double x0 = X[0][i], x1 = X[1][i], x2 = X[2][i], wx = X[6][i];
            const double px0 = -kInvFourPi * X[3][i], px1 = -kInvFourPi * X[4][i],
                         px2 = -kInvFourPi * X[5][i];
            for (int j = 0; j < lanes; ++j) {
                const int k = j0 + j;
                const double r0 = x0 - Y[0][k], r1 = x1 - Y[1][k], r2 = x2 - Y[2][k];
                const double invR = 1.0 / std::sqrt(r0 * r0 + r1 * r1 + r2 * r2);
                const double wInvR = wx * Y[6][k] * invR;
                const double wInvR3 = wInvR * invR * invR;
                const double s0 = wInvR3 * r0, s1 = wInvR3 * r1, s2 = wInvR3 * r2;
                lane[0][j] += wInvR;
                lane[1][j] += s0 * r0;
                lane[2][j] += s0 * r1;
                lane[3][j] += s0 * r2;
                lane[4][j] += s1 * r1;
                lane[5][j] += s1 * r2;
                lane[6][j] += s2 * r2;
                if constexpr (kDoubleLayer) {
                    const double kXY = s0 * ny0 + s1 * ny1 + s2 * ny2;  // (x - y).n_y / (4 pi r^3)
                    const double kYX = s0 * nx0 + s1 * nx1 + s2 * nx2;  // times -1 / (4 pi) below
                    lane[7][j] += kXY * Y[3][k];
                    lane[8][j] += kXY * Y[4][k];
                    lane[9][j] += kXY * Y[5][k];
                    lane[10][j] += kYX * px0;
                    lane[11][j] += kYX * px1;
                    lane[12][j] += kYX * px2;
                }
            }
        }
        for (int sum = 0; sum < (kDoubleLayer ? kSums : 7); ++sum)
            for (int j = 0; j < lanes; ++j) total[sum] += lane[sum][j];
    }
    PairIntegrals out;
    out.inverseDistance = total[0];
    out.dyadic << total[1], total[2], total[3], total[2], total[4], total[5], total[3], total[5], total[6];
    out.doubleLayerXY << total[7], total[8], total[9];
    out.doubleLayerYX << total[10], total[11], total[12];
    return out;
}

}  // namespace

PairIntegrals integrateSeparated(const Panel& x, const PanelPoints& px, const Panel& y, const PanelPoints& py,
                                 bool doubleLayer) {
    if (py.count >= 4)
        return doubleLayer ? separatedSums<true>(x, px, y, py) : separatedSums<false>(x, px, y, py);
    // Too few lanes to pay for the lane sums (the 3-point rule of far pairs): one point pair at a time.
    Accumulator acc{x.normal, y.normal, doubleLayer, {}};
    const int nx = px.count, ny = py.count;
    for (int i = 0; i < nx; ++i) {
        const double a[3] = {px.data[i], px.data[nx + i], px.data[2 * nx + i]};
        const double phiX[3] = {px.data[3 * nx + i], px.data[4 * nx + i], px.data[5 * nx + i]};
        for (int j = 0; j < ny; ++j) {
            const double b[3] = {py.data[j], py.data[ny + j], py.data[2 * ny + j]};
            const double phiY[3] = {py.data[3 * ny + j], py.data[4 * ny + j], py.data[5 * ny + j]};
            acc.add(a, b, phiX, phiY, px.data[6 * nx + i] * py.data[6 * ny + j]);
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

PairIntegrals integrateSingular(const Panel& x, const Panel& y, const QuadratureSettings& settings,
                                bool doubleLayer) {
    const PairRelation relation = relationOf(x, y);
    Accumulator acc{
        x.normal, y.normal, doubleLayer && relation != PairRelation::Identical && !coplanar(x, y), {}};
    integrateSingular(x, y, relation,
                      relation == PairRelation::Identical    ? settings.identicalPoints
                      : relation == PairRelation::CommonEdge ? settings.edgePoints
                                                             : settings.vertexPoints,
                      acc);
    return acc.result();
}

QuadraturePanel::QuadraturePanel(const Panel& p, const QuadratureSettings& s)
    : panel(p), centroid(centroidOf(p.corners)), diameter(diameterOf(p.corners)) {
    for (int level = 0; level < QuadratureSettings::kSeparatedLevels; ++level)
        points[level] = PanelPoints(p, s.levelDegrees[level]);
}

namespace {

// A triangle inside a panel: its corners and each corner's barycentric coordinates in the panel
// (the panel's hat values there).
struct SubPanel {
    Corners corners;
    Corners hats;
    double area, diameter;
    Eigen::Vector3d centroid;
};

SubPanel subPanel(const Corners& corners, const Corners& hats) {
    return {corners, hats, 0.5 * (corners[1] - corners[0]).cross(corners[2] - corners[0]).norm(),
            diameterOf(corners), centroidOf(corners)};
}

SubPanel wholePanel(const Panel& p) {
    return subPanel(p.corners,
                    {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()});
}

// The four triangles of the midpoint split.
std::array<SubPanel, 4> quarters(const SubPanel& s) {
    const auto& c = s.corners;
    const auto& h = s.hats;
    const Corners mc = {0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0])};
    const Corners mh = {0.5 * (h[0] + h[1]), 0.5 * (h[1] + h[2]), 0.5 * (h[2] + h[0])};
    return {subPanel({c[0], mc[0], mc[2]}, {h[0], mh[0], mh[2]}),
            subPanel({mc[0], c[1], mc[1]}, {mh[0], h[1], mh[1]}),
            subPanel({mc[2], mc[1], c[2]}, {mh[2], mh[1], h[2]}),
            subPanel({mc[0], mc[1], mc[2]}, {mh[0], mh[1], mh[2]})};
}

double etaOf(const SubPanel& x, const SubPanel& y) {
    return separationRatio(x.centroid, x.diameter, y.centroid, y.diameter);
}

// The pair's integrals as a sum over sub-pairs: the nearest sub-pair below subPairRatio has its
// larger triangle split (first of equals: deterministic) while the count stays within
// maxSubPairs; each sub-pair then takes its own level's rule.
void addSubdivided(const SubPanel& x, const SubPanel& y, const QuadratureSettings& s, Accumulator& acc) {
    std::vector<std::pair<SubPanel, SubPanel>> pairs{{x, y}};
    while (static_cast<int>(pairs.size()) + 3 <= s.maxSubPairs) {
        int nearest = -1;
        double nearestEta = s.subPairRatio;
        for (int i = 0; i < static_cast<int>(pairs.size()); ++i) {
            const double eta = etaOf(pairs[i].first, pairs[i].second);
            if (eta < nearestEta) {
                nearest = i;
                nearestEta = eta;
            }
        }
        if (nearest < 0) break;
        const auto [a, b] = pairs[nearest];
        const bool splitA = a.diameter >= b.diameter;
        const std::array<SubPanel, 4> children = quarters(splitA ? a : b);
        pairs[nearest] = splitA ? std::make_pair(children[0], b) : std::make_pair(a, children[0]);
        for (int c = 1; c < 4; ++c)
            pairs.push_back(splitA ? std::make_pair(children[c], b) : std::make_pair(a, children[c]));
    }
    std::vector<std::array<double, 6>> yp;  // b's points and hat values, once per sub-pair
    for (const auto& [a, b] : pairs) {
        const TriangleRule& rule = triangleRule(separatedRuleDegree(etaOf(a, b), s));
        const int count = static_cast<int>(rule.points.size());
        yp.resize(count);
        for (int j = 0; j < count; ++j) {
            const auto& q = rule.points[j];
            for (int k = 0; k < 3; ++k) {
                yp[j][k] = q.l0 * b.corners[0][k] + q.l1 * b.corners[1][k] + q.l2 * b.corners[2][k];
                yp[j][3 + k] = q.l0 * b.hats[0][k] + q.l1 * b.hats[1][k] + q.l2 * b.hats[2][k];
            }
        }
        for (const auto& p : rule.points) {
            double xp[3], phiX[3];
            for (int k = 0; k < 3; ++k) {
                xp[k] = p.l0 * a.corners[0][k] + p.l1 * a.corners[1][k] + p.l2 * a.corners[2][k];
                phiX[k] = p.l0 * a.hats[0][k] + p.l1 * a.hats[1][k] + p.l2 * a.hats[2][k];
            }
            for (int j = 0; j < count; ++j)
                acc.add(xp, yp[j].data(), phiX, yp[j].data() + 3, p.w * a.area * rule.points[j].w * b.area);
        }
    }
}

PairIntegrals integrateSubdivided(const Panel& x, const Panel& y, const QuadratureSettings& s,
                                  bool doubleLayer) {
    Accumulator acc{x.normal, y.normal, doubleLayer, {}};
    addSubdivided(wholePanel(x), wholePanel(y), s, acc);
    return acc.result();
}

}  // namespace

PairIntegrals integratePair(const Panel& x, const Panel& y, const QuadratureSettings& settings) {
    if (relationOf(x, y) != PairRelation::Separated) return integrateSingular(x, y, settings);
    const double eta = separationRatio(centroidOf(x.corners), diameterOf(x.corners), centroidOf(y.corners),
                                       diameterOf(y.corners));
    if (eta < settings.subdivisionRatio) return integrateSubdivided(x, y, settings, true);
    const int degree = separatedRuleDegree(eta, settings);
    return integrateSeparated(x, PanelPoints(x, degree), y, PanelPoints(y, degree));
}

PairIntegrals integrateSeparated(const QuadraturePanel& x, const QuadraturePanel& y,
                                 const QuadratureSettings& settings, bool doubleLayer) {
    const double eta = separationRatio(x.centroid, x.diameter, y.centroid, y.diameter);
    if (eta < settings.subdivisionRatio) return integrateSubdivided(x.panel, y.panel, settings, doubleLayer);
    const int level = separatedRuleLevel(eta, settings);
    return integrateSeparated(x.panel, x.points[level], y.panel, y.points[level], doubleLayer);
}

PairIntegrals integratePair(const QuadraturePanel& x, const QuadraturePanel& y,
                            const QuadratureSettings& settings) {
    if (relationOf(x.panel, y.panel) != PairRelation::Separated)
        return integrateSingular(x.panel, y.panel, settings);
    return integrateSeparated(x, y, settings);
}

}  // namespace btfracture
