// SPDX-License-Identifier: Zlib
#include <btFracture/bem/CrackSystem.h>

#include <btFracture/bem/BoundaryOperators.h>
#include <btFracture/bem/GalerkinBlocks.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ParallelProduct.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <map>

namespace btfracture {
namespace {

// Surface triangles with a crack mouth running along one of their edges through crack nodes
// inside that edge (FORMULATION.md, "Mouth"): each is split into a fan of pieces from its
// opposite corner, so that the cut surface hats of those nodes are P1 on the pieces and every
// pair touching the mouth shares whole edges or corners. Piece ids: surface node ids for surface
// nodes, nodeCount + crack node for the crack nodes inside the edge.
struct MouthPiece {
    QuadraturePanel panel;
    std::array<int, 3> crackNode;  // crack node at each corner, -1: none
};
using MouthSplit = std::map<int, std::vector<MouthPiece>>;  // surface triangle -> pieces

MouthSplit splitAlongMouths(const SurfaceMesh& mesh, const CrackMesh& cracks, const QuadratureSettings& q) {
    const int n = mesh.nodeCount();
    std::map<std::array<int, 2>, std::vector<std::pair<double, int>>> onEdge;  // -> (t along, crack node)
    std::map<int, int> crackNodeAt;                                            // surface node -> crack node
    for (int i = 0; i < cracks.nodeCount(); ++i) {
        if (cracks.surfaceNodeOf(i) >= 0) crackNodeAt.emplace(cracks.surfaceNodeOf(i), i);
        const auto& e = cracks.surfaceEdgeOf(i);
        if (e[0] < 0) continue;
        const Eigen::Vector3d a = mesh.node(e[0]), ab = mesh.node(e[1]) - a;
        onEdge[e].emplace_back((cracks.node(i) - a).dot(ab) / ab.squaredNorm(), i);
    }
    MouthSplit out;
    for (auto& [edge, points] : onEdge) {
        std::sort(points.begin(), points.end());
        for (int t : mesh.trianglesAtNode(edge[0])) {
            const auto& tri = mesh.triangle(t);
            int k = 0;  // the corner where the edge starts in t's orientation
            while (k < 3 && !((tri[k] == edge[0] && tri[(k + 1) % 3] == edge[1]) ||
                              (tri[k] == edge[1] && tri[(k + 1) % 3] == edge[0])))
                ++k;
            if (k == 3) continue;
            if (out.count(t))
                throw Error("crack system: a crack mouth runs along two edges of surface triangle " +
                            std::to_string(t) + " (not supported)");
            const int apex = tri[(k + 2) % 3];
            std::vector<std::pair<int, int>> line;  // (panel id, crack node) from tri[k] to tri[k+1]
            auto surfaceVertex = [&](int s) {
                const auto it = crackNodeAt.find(s);
                return std::pair{s, it == crackNodeAt.end() ? -1 : it->second};
            };
            line.push_back(surfaceVertex(tri[k]));
            const bool forward = tri[k] == edge[0];
            for (std::size_t j = 0; j < points.size(); ++j) {
                const int node = points[forward ? j : points.size() - 1 - j].second;
                line.emplace_back(n + node, node);
            }
            line.push_back(surfaceVertex(tri[(k + 1) % 3]));
            auto position = [&](const std::pair<int, int>& v) {
                return v.first < n ? mesh.node(v.first) : cracks.node(v.second);
            };
            for (std::size_t j = 0; j + 1 < line.size(); ++j) {
                Panel panel{{line[j].first, line[j + 1].first, apex},
                            {position(line[j]), position(line[j + 1]), mesh.node(apex)},
                            mesh.normal(t),
                            0.0};
                panel.area =
                    0.5 *
                    (panel.corners[1] - panel.corners[0]).cross(panel.corners[2] - panel.corners[0]).norm();
                out[t].push_back({QuadraturePanel(panel, q), {line[j].second, line[j + 1].second, -1}});
            }
        }
    }
    return out;
}

// Surface curl n x grad(lambda_k) of the barycentric coordinate of corner k of a flat panel.
Eigen::Vector3d pieceCurl(const Panel& p, int k) {
    const Eigen::Vector3d edge = p.corners[(k + 2) % 3] - p.corners[(k + 1) % 3];
    return p.normal.cross(p.normal.cross(edge) / (2.0 * p.area));
}

// One triangle carrying (parts of) crack basis functions: a crack triangle (crack hats), or a
// surface triangle or piece of one on the + side of a mouth node (the surface hat of that node
// cut along the mouth, FORMULATION.md). Panel ids: surface node ids for surface nodes and mouth
// nodes on them, nodeCount + crack node for the others, so that pairs sharing a node get the
// singular rules.
struct BasisElement {
    QuadraturePanel panel;
    std::array<Eigen::Vector3d, 3> curl;
    std::array<int, 3> unknown;  // crack unknown of each corner, -1: none
    int surfaceTriangle;         // the surface triangle it lies on, -1 for a crack triangle
};

// The elements of the given unknowns' basis functions.
std::vector<BasisElement> basisElements(const SurfaceMesh& mesh, const CrackMesh& cracks,
                                        const std::vector<int>& unknowns, const MouthSplit& split,
                                        const QuadratureSettings& q) {
    const int n = mesh.nodeCount();
    auto idOf = [&](int node) {
        return cracks.surfaceNodeOf(node) >= 0 ? cracks.surfaceNodeOf(node) : node + n;
    };
    std::vector<int> triangles;
    for (int k : unknowns)
        for (int t : cracks.trianglesAtNode(cracks.nodeOfUnknown()[k])) triangles.push_back(t);
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    std::vector<BasisElement> out;
    for (int t : triangles) {
        const auto& tri = cracks.triangle(t);
        Panel panel = cracks.panel(t, 0);
        for (int k = 0; k < 3; ++k) panel.ids[k] = idOf(tri[k]);
        BasisElement e{QuadraturePanel(panel, q), {}, {}, -1};
        for (int k = 0; k < 3; ++k) {
            e.curl[k] = cracks.operatorCurl(t, k);
            e.unknown[k] = cracks.unknownOf(tri[k]);
        }
        out.push_back(e);
    }
    std::map<std::pair<int, int>, int> cutHat;  // (surface triangle, piece or -1) -> element
    auto element = [&](int tau, int piece) -> BasisElement& {
        auto it = cutHat.find({tau, piece});
        if (it == cutHat.end()) {
            it = cutHat.emplace(std::pair{tau, piece}, static_cast<int>(out.size())).first;
            out.push_back({piece < 0 ? QuadraturePanel(panelOf(mesh, tau), q) : split.at(tau)[piece].panel,
                           {},
                           {-1, -1, -1},
                           tau});
        }
        return out[it->second];
    };
    for (int k : unknowns) {
        const int node = cracks.nodeOfUnknown()[k];
        if (!cracks.isMouth(node)) continue;
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        for (int t : cracks.trianglesAtNode(node)) normal += cracks.normal(t);
        const int s = cracks.surfaceNodeOf(node);
        const std::vector<int>& around = mesh.trianglesAtNode(s >= 0 ? s : cracks.surfaceEdgeOf(node)[0]);
        for (int tau : around) {
            if ((mesh.centroid(tau) - cracks.node(node)).dot(normal) <= 0.0) continue;
            const auto pieces = split.find(tau);
            if (pieces == split.end()) {
                if (s < 0) continue;  // only the split triangles of its edge carry an edge node's hat
                BasisElement& e = element(tau, -1);
                for (int c = 0; c < 3; ++c)
                    if (mesh.triangle(tau)[c] == s) {
                        e.curl[c] = mesh.hatCurl(tau, c);
                        e.unknown[c] = k;
                    }
                continue;
            }
            for (int p = 0; p < static_cast<int>(pieces->second.size()); ++p)
                for (int c = 0; c < 3; ++c)
                    if (pieces->second[p].crackNode[c] == node) {
                        BasisElement& e = element(tau, p);
                        e.curl[c] = pieceCurl(e.panel.panel, c);
                        e.unknown[c] = k;
                    }
        }
    }
    return out;
}

PairIntegrals integrate(const QuadraturePanel& x, const QuadraturePanel& y, const QuadratureSettings& q,
                        bool doubleLayer) {
    if (relationOf(x.panel, y.panel) == PairRelation::Separated)
        return integrateSeparated(x, y, q, doubleLayer);
    return integrateSingular(x.panel, y.panel, q);
}

// assembleCrackSurfaceCoupling with the mouth split already made.
CrackSurfaceCoupling assembleCoupling(const ElasticSolver& solver, const CrackMesh& cracks,
                                      const std::vector<int>& unknowns, CouplingBlocks blocks,
                                      const MouthSplit& split) {
    const SurfaceMesh& mesh = solver.mesh();
    const int n = mesh.nodeCount(), m = mesh.triangleCount();
    const double mu = solver.material().shearModulus(), nu = solver.material().poissonRatio();
    const QuadratureSettings& q = solver.settings().quadrature;
    std::map<int, int> column;  // crack unknown -> local column
    for (int i = 0; i < static_cast<int>(unknowns.size()); ++i) column[unknowns[i]] = i;
    const bool withLoad = blocks == CouplingBlocks::SurfaceAndLoad;
    CrackSurfaceCoupling out{Eigen::MatrixXd::Zero(3 * n, 3 * unknowns.size()),
                             Eigen::MatrixXd::Zero(withLoad ? 3 * unknowns.size() : 0, withLoad ? 3 * m : 0)};
    const std::vector<BasisElement> support = basisElements(mesh, cracks, unknowns, split, q);
    std::vector<std::array<int, 3>> columns(support.size());
    for (std::size_t e = 0; e < support.size(); ++e)
        for (int b = 0; b < 3; ++b) {
            const auto it = column.find(support[e].unknown[b]);
            columns[e][b] = it == column.end() ? -1 : 3 * it->second;
        }
    // Each element writes only its own unknowns' columns of C and rows of G, but two elements
    // share unknowns: loop over surface triangles in parallel instead, each writing its own
    // nodes' rows of C (coloured) and its own columns of G.
    const std::vector<QuadraturePanel> surfacePanels = quadraturePanels(mesh, q);
    const auto colours = colourTrianglesByNodes(mesh);
    for (const auto& group : colours) {
        const int count = static_cast<int>(group.size());
#pragma omp parallel for schedule(dynamic, 4)
        for (int g = 0; g < count; ++g) {
            const int sigma = group[g];
            const QuadraturePanel& surface = surfacePanels[sigma];
            std::array<Eigen::Vector3d, 3> surfaceCurl;
            for (int a = 0; a < 3; ++a) surfaceCurl[a] = mesh.hatCurl(sigma, a);
            const auto pieces = split.find(sigma);
            for (std::size_t e = 0; e < support.size(); ++e) {
                const BasisElement& crack = support[e];
                // x on the surface (piece by piece where a mouth splits it), y on the element.
                PairIntegrals pi;
                if (pieces == split.end()) {
                    pi = integrate(surface, crack.panel, q, withLoad);
                } else {
                    for (const MouthPiece& piece : pieces->second) {
                        const PairIntegrals part = integrate(piece.panel, crack.panel, q, withLoad);
                        pi.inverseDistance += part.inverseDistance;
                        pi.dyadic += part.dyadic;
                        pi.doubleLayerXY += part.doubleLayerXY;
                        pi.doubleLayerYX += part.doubleLayerYX;
                    }
                }
                const PairCoefficients coeff = coefficientsOf(pi, mu, nu);
                for (int b = 0; b < 3; ++b) {
                    const int col = columns[e][b];
                    if (col < 0) continue;
                    const Eigen::Vector3d& d = crack.curl[b];
                    double P[9];
                    symTimesCross(coeff.L, d.data(), P);
                    for (int a = 0; a < 3; ++a) {
                        const int row = 3 * mesh.triangle(sigma)[a];
                        addStiffnessBlock(surfaceCurl[a].data(), d.data(), P, mu * coeff.a, 1.0,
                                          [&](int i, int j, double v) { out.C(row + i, col + j) += v; });
                    }
                    // Test function on the element against the traction of sigma (the mass term
                    // only where a cut surface hat lies on sigma itself).
                    if (withLoad) {
                        const double mass =
                            crack.surfaceTriangle == sigma ? crack.panel.panel.area / 6.0 : 0.0;
                        addLoadBlock(d.data(), coeff, mu, mass - pi.doubleLayerXY[b],
                                     [&](int i, int j, double v) { out.G(col + i, 3 * sigma + j) += v; });
                    }
                }
            }
        }
    }
    return out;
}

}  // namespace

CrackSurfaceCoupling assembleCrackSurfaceCoupling(const ElasticSolver& solver, const CrackMesh& cracks,
                                                  const std::vector<int>& unknowns, CouplingBlocks blocks) {
    return assembleCoupling(solver, cracks, unknowns, blocks,
                            splitAlongMouths(solver.mesh(), cracks, solver.settings().quadrature));
}

CrackSystem::CrackSystem(const ElasticSolver& solver, CrackMesh& cracks, Blocks blocks)
    : solver_(solver), cracks_(cracks), blocks_(blocks) {
    const int n3 = 3 * solver.mesh().nodeCount(), m3 = 3 * solver.mesh().triangleCount();
    C_.resize(n3, 0);
    G_.resize(0, m3);
    D_.resize(0, 0);
}

const Eigen::MatrixXd& CrackSystem::crackCrackBlock() const {
    if (blocks_ != Blocks::Keep)
        throw Error("CrackSystem: D is folded into the factor (construct with Blocks::Keep)");
    return D_;
}

int CrackSystem::update() {
    cracks_.refreshUnknowns(solver_.mesh());
    const int total = cracks_.unknownCount();
    if (total == assembledUnknowns_) return 0;
    std::vector<int> fresh(total - assembledUnknowns_);
    for (int i = 0; i < static_cast<int>(fresh.size()); ++i) fresh[i] = assembledUnknowns_ + i;
    const int old3 = 3 * assembledUnknowns_, new3 = 3 * total, added = new3 - old3;

    // Surface-crack coupling for the new unknowns: new columns of C, new rows of G.
    const QuadratureSettings& q = solver_.settings().quadrature;
    const MouthSplit split = splitAlongMouths(solver_.mesh(), cracks_, q);
    const CrackSurfaceCoupling coupling =
        assembleCoupling(solver_, cracks_, fresh, CouplingBlocks::SurfaceAndLoad, split);

    // Crack-crack block D in the new unknowns' columns (their rows follow by symmetry).
    Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(new3, added);
    const double mu = solver_.material().shearModulus(), nu = solver_.material().poissonRatio();
    std::vector<int> all(total);
    for (int k = 0; k < total; ++k) all[k] = k;
    const std::vector<BasisElement> elements = basisElements(solver_.mesh(), cracks_, all, split, q);
    const int first = assembledUnknowns_;
    std::vector<char> touchesFresh(elements.size());
    for (std::size_t e = 0; e < elements.size(); ++e)
        touchesFresh[e] = std::any_of(elements[e].unknown.begin(), elements[e].unknown.end(),
                                      [&](int k) { return k >= first; });
    // Each unordered pair once (bit-exact symmetry of D); its block and the transposed block,
    // each entry kept where its column is a new unknown.
    auto addBlock = [&](const BasisElement& x, const BasisElement& y, const PairCoefficients& coeff,
                        bool transposed) {
        for (int b = 0; b < 3; ++b) {
            const int l = y.unknown[b];
            if (l < 0) continue;
            const Eigen::Vector3d& d = y.curl[b];
            double P[9];
            symTimesCross(coeff.L, d.data(), P);
            for (int a = 0; a < 3; ++a) {
                const int k = x.unknown[a];
                if (k < 0 || (transposed ? k : l) < first) continue;
                addStiffnessBlock(x.curl[a].data(), d.data(), P, mu * coeff.a, 1.0,
                                  [&](int i, int j, double v) {
                                      if (transposed)
                                          columns(3 * l + j, 3 * (k - first) + i) += v;
                                      else
                                          columns(3 * k + i, 3 * (l - first) + j) += v;
                                  });
            }
        }
    };
    // The pairs' integrals in parallel, then their blocks added in pair order (deterministic).
    std::vector<std::pair<int, int>> pairs;
    const int count = static_cast<int>(elements.size());
    for (int x = 0; x < count; ++x)
        for (int y = x; y < count; ++y)
            if (touchesFresh[x] || touchesFresh[y]) pairs.emplace_back(x, y);
    std::vector<PairCoefficients> coeffs(pairs.size());
#pragma omp parallel for schedule(dynamic, 64)
    for (int i = 0; i < static_cast<int>(pairs.size()); ++i)
        coeffs[i] = coefficientsOf(
            integratePair(elements[pairs[i].first].panel, elements[pairs[i].second].panel, q), mu, nu);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto [x, y] = pairs[i];
        addBlock(elements[x], elements[y], coeffs[i], false);
        if (y != x) addBlock(elements[x], elements[y], coeffs[i], true);
    }
    Eigen::MatrixXd newD;
    if (blocks_ == Blocks::Keep) newD = columns;

    // Schur complement columns S(:, new) = D(:, new) - C^T K_R^-1 K^T C_new; the new rows are
    // their transpose (S is factored as symmetric).
    const Eigen::MatrixXd H = regularisedLoadSolve(coupling.C);
    if (old3 > 0) columns.topRows(old3) -= transposedProduct(C_, H);
    columns.bottomRows(added) -= transposedProduct(coupling.C, H);
    bool dense = denseSchur_.size() > 0;
    if (!dense && !schur_.extend(columns, 1e-15)) {
        logf(LogLevel::Info, "crack system: the Schur complement of ", total,
             " crack unknowns is not positive definite; factored by LU from here on");
        dense = true;
    }
    if (dense) {
        Eigen::MatrixXd grown(new3, new3);
        grown.topLeftCorner(old3, old3) = denseSchur_.size() > 0 ? denseSchur_ : schur_.product();
        grown.rightCols(added) = columns;
        grown.bottomLeftCorner(added, old3) = columns.topRows(old3).transpose();
        Eigen::PartialPivLU<Eigen::MatrixXd> lu(grown);
        if (!(lu.rcond() > 1e-15))
            throw Error("crack system: the Schur complement of " + std::to_string(total) +
                        " crack unknowns is singular (reciprocal condition " + std::to_string(lu.rcond()) +
                        "); the crack mesh is probably degenerate (slivers, overlapping sheets)");
        denseSchur_ = std::move(grown);
        lu_ = std::move(lu);
        schur_ = BorderedCholesky();
    }

    C_.conservativeResize(Eigen::NoChange, new3);
    C_.rightCols(added) = coupling.C;
    G_.conservativeResize(new3, Eigen::NoChange);
    G_.bottomRows(added) = coupling.G.cast<float>();
    if (blocks_ == Blocks::Keep) {
        D_.conservativeResize(new3, new3);
        D_.rightCols(added) = newD;
        D_.bottomLeftCorner(added, old3) = newD.topRows(old3).transpose();
    }
    assembledUnknowns_ = total;
    return static_cast<int>(fresh.size());
}

CrackSystem::Solution CrackSystem::solve(const Eigen::VectorXd& q) const {
    Solution s;
    const Eigen::VectorXd b = solver_.displacements(q);  // K_R^-1 K^T F q, checked
    if (assembledUnknowns_ == 0) {
        s.displacements = b;
        s.openings.resize(0);
        return s;
    }
    s.openings = loadOnCracks(q) - C_.transpose() * b;
    if (denseSchur_.size() > 0) {
        const Eigen::VectorXd rhs = s.openings;
        s.openings = lu_.solve(rhs);
        const double residual = (denseSchur_ * s.openings - rhs).norm() / std::max(rhs.norm(), 1e-300);
        if (!(residual <= 1e-8))
            throw Error("crack system: Schur complement solve failed (relative residual " +
                        std::to_string(residual) + "); the crack mesh is probably degenerate");
    } else {
        schur_.solveInPlace(s.openings);
    }
    if (!s.openings.allFinite())
        throw Error(
            "crack system: the Schur complement solve gave NaN or Inf; the crack mesh is probably "
            "degenerate");
    s.displacements = b - regularisedLoadSolve(C_ * s.openings);
    return s;
}

CrackSystem::Solution CrackSystem::solveMonolithic(const Eigen::VectorXd& q) const {
    const Eigen::MatrixXd& D = crackCrackBlock();
    const Eigen::MatrixXd& K = solver_.stiffness();
    const int n3 = static_cast<int>(K.rows()), k3 = 3 * assembledUnknowns_;
    const Eigen::MatrixXd& T = solver_.regulariser();
    Eigen::MatrixXd A(n3 + k3, n3 + k3);
    A.topLeftCorner(n3, n3) = K.transpose() * K + solver_.regularisationWeight() * T.transpose() * T;
    A.topRightCorner(n3, k3) = K.transpose() * C_;
    A.bottomLeftCorner(k3, n3) = C_.transpose();
    A.bottomRightCorner(k3, k3) = D;
    Eigen::VectorXd rhs(n3 + k3);
    rhs.head(n3) = K.transpose() * (solver_.operators().tractionToLoad * q);
    rhs.tail(k3) = loadOnCracks(q);
    const Eigen::VectorXd x = A.partialPivLu().solve(rhs);
    return {x.head(n3), x.tail(k3)};
}

Eigen::MatrixXd CrackSystem::regularisedLoadSolve(const Eigen::MatrixXd& b) const {
    return solver_.solveRegularised(transposedProduct(solver_.stiffness(), b));
}

Eigen::VectorXd CrackSystem::loadOnCracks(const Eigen::VectorXd& q) const {
    constexpr int kRows = 64;
    Eigen::VectorXd out(G_.rows());
    for (Eigen::Index r = 0; r < G_.rows(); r += kRows) {
        const Eigen::Index h = std::min<Eigen::Index>(kRows, G_.rows() - r);
        out.segment(r, h).noalias() = G_.middleRows(r, h).cast<double>() * q;
    }
    return out;
}

std::size_t CrackSystem::matrixBytes() const {
    return sizeof(double) * (C_.size() + D_.size() + 2 * denseSchur_.size()) + sizeof(float) * G_.size() +
           schur_.bytes();
}

Eigen::VectorXd CrackSystem::nodalOpenings(const Solution& s) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(3 * cracks_.nodeCount());
    for (int k = 0; k < assembledUnknowns_; ++k)
        out.segment<3>(3 * cracks_.nodeOfUnknown()[k]) = s.openings.segment<3>(3 * k);
    return out;
}

}  // namespace btfracture
