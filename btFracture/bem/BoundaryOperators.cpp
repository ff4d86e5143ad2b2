// SPDX-License-Identifier: Zlib
#include <btFracture/bem/BoundaryOperators.h>

#include <btFracture/bem/GalerkinBlocks.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

// Per-triangle data the assembly loop reads many times.
struct AssemblyCache {
    std::vector<QuadraturePanel> panels;
    std::vector<std::array<Eigen::Vector3d, 3>> curls;  // n x grad(phi_a), constant per triangle
    // Node-sharing partners tau >= t of each triangle t with their Sauter-Schwab integrals.
    std::vector<std::vector<std::pair<int, PairIntegrals>>> singular;
};

AssemblyCache buildCache(const SurfaceMesh& mesh, const QuadratureSettings& q) {
    const int m = mesh.triangleCount();
    AssemblyCache c;
    c.panels = quadraturePanels(mesh, q);
    c.curls.resize(m);
    c.singular.resize(m);
    for (int t = 0; t < m; ++t)
        for (int a = 0; a < 3; ++a) c.curls[t][a] = mesh.hatCurl(t, a);
#pragma omp parallel for schedule(dynamic, 16)
    for (int t = 0; t < m; ++t) {
        std::vector<int> partners;
        for (int v : mesh.triangle(t))
            for (int other : mesh.trianglesAtNode(v))
                if (other >= t) partners.push_back(other);
        std::sort(partners.begin(), partners.end());
        partners.erase(std::unique(partners.begin(), partners.end()), partners.end());
        for (int other : partners)
            c.singular[t].emplace_back(other, integrateSingular(c.panels[t].panel, c.panels[other].panel, q));
    }
    return c;
}

// dst += src^T in cache-sized tiles (a plain transposed read misses the cache on every
// element of these large matrices). Each entry is written once: deterministic in parallel.
template <class Dst, class Src>
void addTransposed(Dst& dst, const Src& src) {
    constexpr int kTile = 64;
    const int rows = static_cast<int>(dst.rows()), cols = static_cast<int>(dst.cols());
#pragma omp parallel for schedule(static)
    for (int i0 = 0; i0 < rows; i0 += kTile)
        for (int j0 = 0; j0 < cols; j0 += kTile) {
            const int h = std::min(kTile, rows - i0), w = std::min(kTile, cols - j0);
            dst.block(i0, j0, h, w) += src.block(j0, i0, w, h).transpose();
        }
}

// A := A + A^T in cache-sized tiles, each tile pair read and written once.
void symmetriseInPlace(Eigen::MatrixXd& A) {
    constexpr int kTile = 64;
    const int n = static_cast<int>(A.rows());
    std::vector<std::pair<int, int>> tiles;
    for (int j0 = 0; j0 < n; j0 += kTile)
        for (int i0 = j0; i0 < n; i0 += kTile) tiles.emplace_back(i0, j0);
#pragma omp parallel for schedule(dynamic, 4)
    for (int t = 0; t < static_cast<int>(tiles.size()); ++t) {
        const int i0 = tiles[t].first, j0 = tiles[t].second;
        const int h = std::min(kTile, n - i0), w = std::min(kTile, n - j0);
        if (i0 == j0) {
            const Eigen::MatrixXd sum = A.block(i0, j0, h, w) + A.block(i0, j0, h, w).transpose();
            A.block(i0, j0, h, w) = sum;
        } else {
            const Eigen::MatrixXd sum = A.block(i0, j0, h, w) + A.block(j0, i0, w, h).transpose();
            A.block(i0, j0, h, w) = sum;
            A.block(j0, i0, w, h) = sum.transpose();
        }
    }
}

}  // namespace

Panel panelOf(const SurfaceMesh& mesh, int t) {
    const auto& tri = mesh.triangle(t);
    return Panel{
        tri, {mesh.node(tri[0]), mesh.node(tri[1]), mesh.node(tri[2])}, mesh.normal(t), mesh.area(t)};
}

std::vector<QuadraturePanel> quadraturePanels(const SurfaceMesh& mesh, const QuadratureSettings& quadrature) {
    std::vector<QuadraturePanel> panels;
    panels.reserve(mesh.triangleCount());
    for (int t = 0; t < mesh.triangleCount(); ++t) panels.emplace_back(panelOf(mesh, t), quadrature);
    return panels;
}

std::vector<std::vector<int>> colourTrianglesByNodes(const SurfaceMesh& mesh) {
    const int m = mesh.triangleCount();
    std::vector<int> colour(m, -1);
    std::vector<std::vector<int>> classes;
    std::vector<char> used;
    for (int t = 0; t < m; ++t) {
        used.assign(classes.size() + 1, 0);
        for (int v : mesh.triangle(t))
            for (int other : mesh.trianglesAtNode(v))
                if (colour[other] >= 0) used[colour[other]] = 1;
        const int c = static_cast<int>(std::find(used.begin(), used.end(), 0) - used.begin());
        if (c == static_cast<int>(classes.size())) classes.emplace_back();
        colour[t] = c;
        classes[c].push_back(t);
    }
    return classes;
}

BoundaryOperators assembleBoundaryOperators(const SurfaceMesh& mesh, const ElasticConstants& material,
                                            const QuadratureSettings& quadrature) {
    const int n = mesh.nodeCount(), m = mesh.triangleCount();
    const double mu = material.shearModulus, nu = material.poissonRatio;
    const AssemblyCache cache = buildCache(mesh, quadrature);

    // Each unordered pair {sigma <= tau} is integrated once, by its lower triangle sigma (the
    // "owner"). The owner writes only rows of its own nodes (of `upper` and F) and rows of its
    // own traction triangle (of `reverse`); triangles of one colour share no node, so owners of
    // one colour never write the same entry, and every entry is summed in a fixed order.
    //   K = U + U^T                (pair blocks for sigma < tau, half of the diagonal pairs)
    //   F = forward + reverse^T    (test hats on sigma / on tau)
    // Row-major scratch: an owner's rows are contiguous, which keeps its writes in cache.
    using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    BoundaryOperators ops;
    // The owners' stiffness blocks U go into K's own storage as U^T (column p of K holds row p
    // of U, contiguous per owner); K = U + U^T is then formed in place.
    ops.stiffness.setZero(3 * n, 3 * n);
    Eigen::MatrixXd& upperTransposed = ops.stiffness;
    ops.tractionToLoad.setZero(3 * n, 3 * m);
    RowMajorMatrix reverse = RowMajorMatrix::Zero(3 * m, 3 * n);

    for (const auto& owners : colourTrianglesByNodes(mesh)) {
        const int count = static_cast<int>(owners.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < count; ++k) {
            const int sigma = owners[k];
            const auto& ownerNodes = mesh.triangle(sigma);
            auto singular = cache.singular[sigma].begin();
            for (int tau = sigma; tau < m; ++tau) {
                PairIntegrals pi;  // x on sigma, y on tau
                if (singular != cache.singular[sigma].end() && singular->first == tau)
                    pi = (singular++)->second;
                else
                    pi = integrateSeparated(cache.panels[sigma], cache.panels[tau], quadrature);
                const PairCoefficients coeff = coefficientsOf(pi, mu, nu);
                const auto& partnerNodes = mesh.triangle(tau);
                const double stiffnessScale = tau == sigma ? 0.5 : 1.0;
                const auto& c = cache.curls[sigma];
                const auto& d = cache.curls[tau];
                // Every block is linear in each curl and the three curls of a triangle sum to
                // zero, so the blocks of corner 2 follow from those of corners 0 and 1.
                double P[2][9];  // L [d_b]
                for (int b = 0; b < 2; ++b) symTimesCross(coeff.L, d[b].data(), P[b]);
                double K[3][3][9];  // K[a][b][3 i + j]
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b)
                        addStiffnessBlock(c[a].data(), d[b].data(), P[b], mu * coeff.a, stiffnessScale,
                                          [&](int i, int j, double v) { K[a][b][3 * i + j] = v; });
                for (int e = 0; e < 9; ++e) {
                    K[0][2][e] = -K[0][0][e] - K[0][1][e];
                    K[1][2][e] = -K[1][0][e] - K[1][1][e];
                    K[2][0][e] = -K[0][0][e] - K[1][0][e];
                    K[2][1][e] = -K[0][1][e] - K[1][1][e];
                    K[2][2][e] = -K[2][0][e] - K[2][1][e];
                }
                double forward[3][9], backward[3][9];  // curl-linear parts of the F blocks
                for (int a = 0; a < 2; ++a) {
                    addLoadBlock(c[a].data(), coeff, mu, 0.0,
                                 [&](int i, int j, double v) { forward[a][3 * i + j] = v; });
                    addLoadBlock(d[a].data(), coeff, mu, 0.0,
                                 [&](int i, int j, double v) { backward[a][3 * i + j] = v; });
                }
                for (int e = 0; e < 9; ++e) {
                    forward[2][e] = -forward[0][e] - forward[1][e];
                    backward[2][e] = -backward[0][e] - backward[1][e];
                }
                for (int ia = 0; ia < 3; ++ia) {
                    const int row = 3 * ownerNodes[ia];
                    for (int ib = 0; ib < 3; ++ib) {
                        const int col = 3 * partnerNodes[ib];
                        for (int i = 0; i < 3; ++i)
                            for (int j = 0; j < 3; ++j)
                                upperTransposed(col + j, row + i) += K[ia][ib][3 * i + j];
                    }
                    // Test hat phi_p on sigma, traction on tau (x on tau, density on sigma).
                    const double scalar =
                        -pi.doubleLayerYX[ia] + (tau == sigma ? mesh.area(sigma) / 6.0 : 0.0);
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            ops.tractionToLoad(row + i, 3 * tau + j) +=
                                forward[ia][3 * i + j] + (i == j ? scalar : 0.0);
                }
                if (tau == sigma) continue;
                for (int ib = 0; ib < 3; ++ib) {
                    // Test hat phi_q on tau, traction on sigma: stored transposed in the owner's rows.
                    const int col = 3 * partnerNodes[ib];
                    const double scalar = -pi.doubleLayerXY[ib];
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            reverse(3 * sigma + j, col + i) +=
                                backward[ib][3 * i + j] + (i == j ? scalar : 0.0);
                }
            }
        }
    }
    symmetriseInPlace(ops.stiffness);
    addTransposed(ops.tractionToLoad, reverse);
    return ops;
}

}  // namespace btfracture
