// SPDX-License-Identifier: Zlib
#pragma once
// Material-independent double integrals over one pair of flat triangles, the only quadrature
// the Galerkin operators need (see FORMULATION.md): after integration by parts the
// hypersingular operator and the adjoint double layer reduce to the weakly singular kernels
// 1/r and r r^T / r^3 with constant densities, plus the Laplace double layer with P1 densities.
#include <btFracture/bem/SauterSchwab.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace btfracture {

// One flat triangle as the quadrature sees it. `ids` are node numbers in one numbering shared
// by both triangles of a pair: shared ids decide the singular case.
struct Panel {
    std::array<int, 3> ids;
    std::array<Eigen::Vector3d, 3> corners;
    Eigen::Vector3d normal;  // unit normal
    double area;
};

struct PairIntegrals {
    double inverseDistance = 0.0;                      // int_x int_y 1/r
    Eigen::Matrix3d dyadic = Eigen::Matrix3d::Zero();  // int_x int_y r r^T / r^3, r = x - y
    // Laplace double layer with P1 density on the other panel:
    // doubleLayerXY[b] = int_x int_y (x - y).n_y / (4 pi r^3) phi_b(y), b = corner of panel y
    // doubleLayerYX[a] = int_y int_x (y - x).n_x / (4 pi r^3) phi_a(x), a = corner of panel x
    Eigen::Vector3d doubleLayerXY = Eigen::Vector3d::Zero();
    Eigen::Vector3d doubleLayerYX = Eigen::Vector3d::Zero();
};

struct QuadratureSettings {
    // Gauss points per axis of the Sauter-Schwab 4-cube (relative errors of the 1/r and r r^T/r^3
    // integrals: about 1e-8 / 1e-6 at 6 points, 1e-7 / 1e-6 at 5 for edge and vertex pairs).
    int identicalPoints = 6;
    int edgePoints = 5;
    int vertexPoints = 5;
    // Regular (separated) pairs: the triangle rule's degree by level, the level by the pair's
    // centroid distance / larger diameter eta: level i while eta < levelRatios[i], the last level
    // beyond. Worst relative error of the r r^T / r^3 integral at each boundary against degree 20
    // (the 1/r and double-layer integrals' lower): degree 8 (16 points) below 1.5, 5 (7 points)
    // 2.7e-4 at 1.5, 4 (6 points) 1e-5 at 3, 2 (3 points) 7e-5 at 6.
    // Nearly touching pairs (eta below subdivisionRatio: a crack element whose corner lies on a
    // surface triangle without sharing its node) split the larger triangle of their nearest
    // sub-pair in four, again and again, until every sub-pair reaches subPairRatio or there are
    // maxSubPairs sub-pairs (bounding the work where two triangles cross or overlap).
    double subdivisionRatio = 0.5;
    double subPairRatio = 1.0;
    int maxSubPairs = 64;
    static constexpr int kSeparatedLevels = 4;
    std::array<double, kSeparatedLevels - 1> levelRatios = {1.5, 3.0, 6.0};
    std::array<int, kSeparatedLevels> levelDegrees = {8, 5, 4, 2};
};

PairRelation relationOf(const Panel& x, const Panel& y);

// Level (QuadratureSettings::levelRatios) and degree of the triangle rule for a separated pair
// whose centroid distance is eta times the larger panel diameter.
int separatedRuleLevel(double eta, const QuadratureSettings& settings);
int separatedRuleDegree(double eta, const QuadratureSettings& settings);

// Quadrature points of one panel for one rule degree, precomputed for the separated-pair loop,
// field by field (x, y, z, the three hat values, weight * area; `count` values each).
struct PanelPoints {
    static constexpr int kFields = 7;
    PanelPoints() = default;
    PanelPoints(const Panel& panel, int degree);
    std::vector<double> data;
    int count = 0;
};

// Separated pair with precomputed points (both at the degree separatedRuleDegree gives).
// Without `doubleLayer` the two double-layer integrals are left zero (a third of the work).
PairIntegrals integrateSeparated(const Panel& x, const PanelPoints& px, const Panel& y, const PanelPoints& py,
                                 bool doubleLayer = true);

// A panel with what every pair it enters reads: centroid, diameter (longest edge) and its points
// at each separated-rule level. Loops that pair one panel with many build it once.
struct QuadraturePanel {
    QuadraturePanel(const Panel& panel, const QuadratureSettings& settings);
    Panel panel;
    Eigen::Vector3d centroid;
    double diameter;
    std::array<PanelPoints, QuadratureSettings::kSeparatedLevels> points;  // by separatedRuleLevel
};
// Identical, edge- or vertex-adjacent pair by Sauter-Schwab quadrature (without `doubleLayer`
// the double-layer integrals are left zero).
PairIntegrals integrateSingular(const Panel& x, const Panel& y, const QuadratureSettings& settings,
                                bool doubleLayer = true);

// Integrates the pair (x, y). Identical, edge- and vertex-adjacent pairs use Sauter-Schwab
// quadrature; separated pairs use triangle rules whose degree grows as the pair gets closer.
// Deterministic; integratePair(y, x) equals integratePair(x, y) with the roles swapped up to
// rounding, so callers that need exact symmetry pass pairs in a canonical order.
PairIntegrals integratePair(const Panel& x, const Panel& y, const QuadratureSettings& settings);
// The same with the points precomputed (equal results).
PairIntegrals integratePair(const QuadraturePanel& x, const QuadraturePanel& y,
                            const QuadratureSettings& settings);
// The separated branch of it alone, for loops that know the pair shares no node.
PairIntegrals integrateSeparated(const QuadraturePanel& x, const QuadraturePanel& y,
                                 const QuadratureSettings& settings, bool doubleLayer = true);

}  // namespace btfracture
