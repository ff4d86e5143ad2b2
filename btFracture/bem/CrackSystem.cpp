// SPDX-License-Identifier: Zlib
#include <btFracture/bem/CrackSystem.h>

#include <btFracture/bem/BoundaryOperators.h>
#include <btFracture/bem/GalerkinBlocks.h>
#include <btFracture/bem/MouthCut.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ParallelProduct.h>
#include <btFracture/core/Timer.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

namespace btfracture {
namespace {

// Surface curl N x grad(f) of the linear function with corner values v on a flat panel with
// operator normal N (any corner order).
Eigen::Vector3d pieceCurl(const Panel& p, const std::array<double, 3>& v) {
    const Eigen::Vector3d twiceArea = (p.corners[1] - p.corners[0]).cross(p.corners[2] - p.corners[0]);
    const Eigen::Vector3d unit = twiceArea.normalized();
    Eigen::Vector3d grad = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
        grad += v[k] * unit.cross(p.corners[(k + 2) % 3] - p.corners[(k + 1) % 3]) / twiceArea.norm();
    return p.normal.cross(grad);
}

// One crack basis function restricted to an element: its unknown, its constant surface curl and
// its values at the element's corners.
struct Restriction {
    int unknown;
    Eigen::Vector3d curl;
    std::array<double, 3> values;
};

// One triangle carrying (parts of) crack basis functions: a crack triangle or piece of one (crack
// hats), or a surface triangle or piece of one on the + side of a mouth (cut surface hats of
// mouth nodes, FORMULATION.md). Panel ids as MouthCut's, so that pairs sharing a node get the
// singular rules.
struct BasisElement {
    QuadraturePanel panel;
    std::vector<Restriction> functions;
    int surfaceTriangle;  // the surface triangle it lies on, -1 for a crack triangle
};

// The element of a mouth piece with the restrictions of the crack unknowns in `wanted`.
BasisElement pieceElement(const MouthPiece& piece, const CrackMesh& cracks, const std::vector<char>& wanted,
                          int surfaceTriangle, const QuadratureSettings& q) {
    BasisElement e{QuadraturePanel(piece.panel, q), {}, surfaceTriangle};
    for (int k = 0; k < 3; ++k)
        for (const auto& [node, value] : piece.weights[k]) {
            const int unknown = cracks.unknownOf(node);
            if (unknown < 0 || !wanted[unknown] || value == 0.0) continue;
            auto it = std::find_if(e.functions.begin(), e.functions.end(),
                                   [&](const Restriction& r) { return r.unknown == unknown; });
            if (it == e.functions.end()) {
                e.functions.push_back({unknown, Eigen::Vector3d::Zero(), {0.0, 0.0, 0.0}});
                it = std::prev(e.functions.end());
            }
            it->values[k] = value;
        }
    for (Restriction& r : e.functions) r.curl = pieceCurl(piece.panel, r.values);
    return e;
}

std::string scientific(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

// Rows per block of the LU factors (48 crack unknowns).
constexpr int kLuBlock = 144;
// At or below this estimate of S's reciprocal condition number the LU treats S as singular.
constexpr double kMinimumRcond = 1e-15;

// ||S x - b|| / (||S|| ||x|| + ||b||), Frobenius norm for S.
double backwardError(const Eigen::MatrixXd& S, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
    return (S * x - b).norm() / std::max(S.norm() * x.norm() + b.norm(), 1e-300);
}

// The backward error of a solve with `lu` for a fixed right-hand side of S (a check of the
// block-pivoted factors' growth, one O(n^2) solve).
double probeBackwardError(const BorderedLU& lu, const Eigen::MatrixXd& S) {
    Eigen::VectorXd b(S.rows());
    for (int i = 0; i < b.size(); ++i) b[i] = 1.0 + (i % 7) / 7.0;
    Eigen::VectorXd x = b;
    lu.solveInPlace(x);
    return x.allFinite() ? backwardError(S, x, b) : std::numeric_limits<double>::infinity();
}

// A hash of a basis function's restriction to one element (corners and values, bit for bit).
std::uint64_t fingerprintOf(const Panel& panel, const std::array<double, 3>& values) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    auto add = [&](double x) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xff)) * 1099511628211ull;
    };
    for (const Eigen::Vector3d& c : panel.corners)
        for (int i = 0; i < 3; ++i) add(c[i]);
    for (double v : values) add(v);
    return h;
}

// The elements of the given unknowns' basis functions.
std::vector<BasisElement> basisElements(const SurfaceMesh& mesh, const CrackMesh& cracks,
                                        const std::vector<int>& unknowns, const MouthCut& cut,
                                        const QuadratureSettings& q) {
    std::vector<char> wanted(cracks.unknownCount(), 0);
    for (int k : unknowns) wanted[k] = 1;
    std::vector<int> triangles;
    for (int k : unknowns)
        for (int t : cracks.trianglesAtNode(cracks.nodeOfUnknown()[k])) triangles.push_back(t);
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    std::vector<BasisElement> out;
    for (int t : triangles) {
        const auto pieces = cut.crackPieces.find(t);
        if (pieces != cut.crackPieces.end()) {
            for (const MouthPiece& piece : pieces->second) {
                BasisElement e = pieceElement(piece, cracks, wanted, -1, q);
                if (!e.functions.empty()) out.push_back(std::move(e));
            }
            continue;
        }
        const auto& tri = cracks.triangle(t);
        Panel panel = cracks.panel(t, 0);
        for (int k = 0; k < 3; ++k) panel.ids[k] = mouthIdOf(mesh, cracks, tri[k]);
        BasisElement e{QuadraturePanel(panel, q), {}, -1};
        for (int k = 0; k < 3; ++k) {
            const int unknown = cracks.unknownOf(tri[k]);
            if (unknown < 0 || !wanted[unknown]) continue;
            std::array<double, 3> values{0.0, 0.0, 0.0};
            values[k] = 1.0;
            e.functions.push_back({unknown, cracks.operatorCurl(t, k), values});
        }
        out.push_back(std::move(e));
    }
    for (const auto& [tau, pieces] : cut.surfacePieces)
        for (const MouthPiece& piece : pieces) {
            BasisElement e = pieceElement(piece, cracks, wanted, tau, q);
            if (!e.functions.empty()) out.push_back(std::move(e));
        }
    return out;
}

PairIntegrals integrate(const QuadraturePanel& x, const QuadraturePanel& y, const QuadratureSettings& q,
                        bool doubleLayer) {
    if (relationOf(x.panel, y.panel) == PairRelation::Separated)
        return integrateSeparated(x, y, q, doubleLayer);
    return integrateSingular(x.panel, y.panel, q, doubleLayer);
}

// assembleCrackSurfaceCoupling with the mouth split already made.
CrackSurfaceCoupling assembleCoupling(const ElasticSolver& solver, const CrackMesh& cracks,
                                      const std::vector<int>& unknowns, CouplingBlocks blocks,
                                      const MouthCut& cut) {
    const SurfaceMesh& mesh = solver.mesh();
    const int n = mesh.nodeCount(), m = mesh.triangleCount();
    const double mu = solver.material().shearModulus(), nu = solver.material().poissonRatio();
    const QuadratureSettings& q = solver.settings().quadrature;
    std::map<int, int> column;  // crack unknown -> local column
    for (int i = 0; i < static_cast<int>(unknowns.size()); ++i) column[unknowns[i]] = i;
    const bool withLoad = blocks == CouplingBlocks::SurfaceAndLoad;
    // C accumulated in place (a row-major copy would hold it twice at thousands of unknowns).
    CrackSurfaceCoupling out{Eigen::MatrixXd::Zero(3 * n, 3 * unknowns.size()),
                             Eigen::MatrixXd::Zero(withLoad ? 3 * unknowns.size() : 0, withLoad ? 3 * m : 0)};
    Eigen::MatrixXd& C = out.C;
    const std::vector<BasisElement> support = basisElements(mesh, cracks, unknowns, cut, q);
    std::vector<std::vector<int>> columns(support.size());  // per element, per function: column of C
    for (std::size_t e = 0; e < support.size(); ++e)
        for (const Restriction& f : support[e].functions) columns[e].push_back(3 * column.at(f.unknown));
    // Each element writes only its own unknowns' columns of C and rows of G, but two elements
    // share unknowns: loop over surface triangles in parallel instead, each writing its own
    // nodes' rows of C (coloured) and its own columns of G.
    const std::vector<QuadraturePanel> surfacePanels = quadraturePanels(mesh, q);
    std::map<int, std::vector<QuadraturePanel>> piecePanels;  // surface triangle -> its pieces
    for (const auto& [sigma, pieces] : cut.surfacePieces)
        for (const MouthPiece& piece : pieces) piecePanels[sigma].emplace_back(piece.panel, q);
    const auto colours = colourTrianglesByNodes(mesh);
    for (const auto& group : colours) {
        const int count = static_cast<int>(group.size());
#pragma omp parallel for schedule(dynamic, 4)
        for (int g = 0; g < count; ++g) {
            const int sigma = group[g];
            const QuadraturePanel& surface = surfacePanels[sigma];
            std::array<Eigen::Vector3d, 3> surfaceCurl;
            for (int a = 0; a < 3; ++a) surfaceCurl[a] = mesh.hatCurl(sigma, a);
            const auto pieces = piecePanels.find(sigma);
            for (std::size_t e = 0; e < support.size(); ++e) {
                const BasisElement& crack = support[e];
                // x on the surface (piece by piece where a mouth splits it), y on the element.
                PairIntegrals pi;
                if (pieces == piecePanels.end()) {
                    pi = integrate(surface, crack.panel, q, withLoad);
                } else {
                    for (const QuadraturePanel& piece : pieces->second) {
                        const PairIntegrals part = integrate(piece, crack.panel, q, withLoad);
                        pi.inverseDistance += part.inverseDistance;
                        pi.dyadic += part.dyadic;
                        pi.doubleLayerXY += part.doubleLayerXY;
                        pi.doubleLayerYX += part.doubleLayerYX;
                    }
                }
                const PairCoefficients coeff = coefficientsOf(pi, mu, nu);
                for (std::size_t i = 0; i < crack.functions.size(); ++i) {
                    const Restriction& f = crack.functions[i];
                    const int col = columns[e][i];
                    const Eigen::Vector3d& d = f.curl;
                    double P[9];
                    symTimesCross(coeff.L, d.data(), P);
                    for (int a = 0; a < 3; ++a) {
                        const int row = 3 * mesh.triangle(sigma)[a];
                        addStiffnessBlock(surfaceCurl[a].data(), d.data(), P, mu * coeff.a, 1.0,
                                          [&](int i, int j, double v) { C(row + i, col + j) += v; });
                    }
                    // Test function on the element against the traction of sigma (the mass term
                    // only where a cut surface hat lies on sigma itself).
                    if (withLoad) {
                        const double sum = f.values[0] + f.values[1] + f.values[2];
                        const double mass =
                            crack.surfaceTriangle == sigma ? crack.panel.panel.area * sum / 6.0 : 0.0;
                        double doubleLayer = 0.0;
                        for (int b = 0; b < 3; ++b) doubleLayer += f.values[b] * pi.doubleLayerXY[b];
                        addLoadBlock(d.data(), coeff, mu, mass - doubleLayer,
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
    return assembleCoupling(solver, cracks, unknowns, blocks, cutAlongMouths(solver.mesh(), cracks));
}

CrackSystem::CrackSystem(const ElasticSolver& solver, CrackMesh& cracks, Blocks blocks)
    : solver_(solver), cracks_(cracks), blocks_(blocks) {
    const int n3 = 3 * solver.mesh().nodeCount(), m3 = 3 * solver.mesh().triangleCount();
    W_.resize(n3, 0);
    if (blocks_ == Blocks::Keep) C_.resize(n3, 0);
    Gt_.resize(m3, 0);
    D_.resize(0, 0);
}

const Eigen::MatrixXd& CrackSystem::surfaceCrackBlock() const {
    if (blocks_ != Blocks::Keep)
        throw Error("CrackSystem: C is kept as L^-1 P C only (construct with Blocks::Keep)");
    return C_;
}

Eigen::VectorXd CrackSystem::surfaceLoadOf(const Eigen::VectorXd& openings) const {
    if (openings.size() != W_.cols())
        throw Error("CrackSystem::surfaceLoadOf: expected " + std::to_string(W_.cols()) +
                    " opening values, got " + std::to_string(openings.size()));
    return solver_.factorTimes(W_ * openings);
}

const Eigen::MatrixXd& CrackSystem::crackCrackBlock() const {
    if (blocks_ != Blocks::Keep)
        throw Error("CrackSystem: D is folded into the factor (construct with Blocks::Keep)");
    return D_;
}

int CrackSystem::update() {
    cracks_.refreshUnknowns(solver_.mesh());
    const int before = assembledUnknowns_;
    if (cracks_.unknownCount() == 0) return 0;
    // A mouth edge the cut could not follow would leave its nodes' cut hats jumping across surface
    // edges (not conforming: S loses positive definiteness). Its nodes new to the system are held
    // at zero instead, the edge front from now on; nodes assembled earlier keep their unknowns.
    MouthCut cut;
    while (true) {
        cut = cutAlongMouths(solver_.mesh(), cracks_);
        std::vector<std::pair<int, int>> hold;
        for (const auto& [a, b] : cut.unfollowedEdges)
            if (cracks_.unknownOf(a) >= assembledUnknowns_ || cracks_.unknownOf(b) >= assembledUnknowns_)
                hold.emplace_back(a, b);
        if (hold.empty()) break;
        logf(LogLevel::Debug, "crack system: ", hold.size(),
             " crack mouth edges could not be followed over the body's surface; their new nodes are held "
             "shut");
        cracks_.holdAsFront(hold, assembledUnknowns_);
    }
    const int unfollowed = static_cast<int>(cut.unfollowedEdges.size());
    if (unfollowed > unfollowedEdges_)
        logf(LogLevel::Info, "crack system: ", unfollowed,
             " crack mouth edges of earlier openings could not be followed ",
             "over the body's surface; their nodes' openings lack the surface part there (FORMULATION.md, "
             "Mouth)");
    unfollowedEdges_ = std::max(unfollowedEdges_, unfollowed);
    const int total = cracks_.unknownCount();
    const QuadratureSettings& q = solver_.settings().quadrature;
    std::vector<int> all(total);
    for (int k = 0; k < total; ++k) all[k] = k;
    const std::vector<BasisElement> elements = basisElements(solver_.mesh(), cracks_, all, cut, q);

    // A cut that changed near a mouth changes the basis functions of unknowns assembled earlier
    // (their pieces and plateau): those are assembled again with the new ones, so that S stays the
    // Galerkin matrix of one cut; every other entry keeps its value.
    std::vector<std::uint64_t> fingerprints(total, 0);
    for (const BasisElement& e : elements)
        for (const Restriction& f : e.functions)
            fingerprints[f.unknown] += fingerprintOf(e.panel.panel, f.values);
    std::vector<int> redo;  // changed unknowns, then the new ones
    for (int k = 0; k < assembledUnknowns_; ++k)
        if (fingerprints[k] != fingerprints_[k]) redo.push_back(k);
    const int changed = static_cast<int>(redo.size());
    for (int k = assembledUnknowns_; k < total; ++k) redo.push_back(k);
    if (redo.empty()) return 0;
    std::vector<int> position(total, -1);  // unknown -> its index in redo
    for (int i = 0; i < static_cast<int>(redo.size()); ++i) position[redo[i]] = i;
    // The factor's order: the unchanged unknowns in their old order (the Cholesky factor loses the
    // changed ones' rows by rank-one updates, the LU is extended again from the first of them), then
    // the changed and the new ones.
    std::vector<int> slotOf(assembledUnknowns_);  // unknown -> its slot in the factor
    for (int s = 0; s < assembledUnknowns_; ++s) slotOf[slots_[s]] = s;
    int first = assembledUnknowns_;  // the first slot whose unknown changed
    for (int i = 0; i < changed; ++i) first = std::min(first, slotOf[redo[i]]);
    std::vector<int> slots;
    std::vector<int> keptRows;  // the unchanged unknowns' rows in the old factor's order
    for (int s = 0; s < assembledUnknowns_; ++s)
        if (position[slots_[s]] < 0) {
            slots.push_back(slots_[s]);
            for (int i = 0; i < 3; ++i) keptRows.push_back(3 * s + i);
        }
    const int kept = static_cast<int>(slots.size());
    slots.insert(slots.end(), redo.begin(), redo.end());
    if (changed > 0)
        logf(LogLevel::Debug, "crack system: the mouth's cut changed ", changed, " of ", assembledUnknowns_,
             " crack unknowns (the first at slot ", first, ")");

    // The changed unknowns' old columns, restored if the grown system turns out singular.
    Eigen::MatrixXd savedW(W_.rows(), 3 * changed), savedC, savedD;
    Eigen::MatrixXf savedG(Gt_.rows(), 3 * changed);
    if (blocks_ == Blocks::Keep) savedC.resize(C_.rows(), 3 * changed), savedD.resize(D_.rows(), 3 * changed);
    for (int i = 0; i < changed; ++i) {
        savedW.middleCols(3 * i, 3) = W_.middleCols(3 * redo[i], 3);
        if (blocks_ == Blocks::Keep) savedC.middleCols(3 * i, 3) = C_.middleCols(3 * redo[i], 3);
        savedG.middleCols(3 * i, 3) = Gt_.middleCols(3 * redo[i], 3);
        if (blocks_ == Blocks::Keep) savedD.middleCols(3 * i, 3) = D_.middleCols(3 * redo[i], 3);
    }
    bool factorTaken = false;
    try {
        const int new3 = 3 * total, redo3 = 3 * static_cast<int>(redo.size());

        // Surface-crack coupling of the redone unknowns: their columns of C, rows of G.
        Timer phase;
        CrackSurfaceCoupling coupling =
            assembleCoupling(solver_, cracks_, redo, CouplingBlocks::SurfaceAndLoad, cut);

        // Crack-crack block D in the redone unknowns' columns (their rows follow by symmetry).
        Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(new3, redo3);
        const double mu = solver_.material().shearModulus(), nu = solver_.material().poissonRatio();
        std::vector<char> touchesRedo(elements.size());
        for (std::size_t e = 0; e < elements.size(); ++e)
            touchesRedo[e] = std::any_of(elements[e].functions.begin(), elements[e].functions.end(),
                                         [&](const Restriction& r) { return position[r.unknown] >= 0; });
        // Each unordered pair once (bit-exact symmetry of D); its block and the transposed block,
        // each entry kept where its column is a redone unknown.
        auto addBlock = [&](const BasisElement& x, const BasisElement& y, const PairCoefficients& coeff,
                            bool transposed) {
            for (const Restriction& fy : y.functions) {
                const int l = fy.unknown;
                const Eigen::Vector3d& d = fy.curl;
                double P[9];
                symTimesCross(coeff.L, d.data(), P);
                for (const Restriction& fx : x.functions) {
                    const int k = fx.unknown;
                    const int column = position[transposed ? k : l];
                    if (column < 0) continue;
                    addStiffnessBlock(fx.curl.data(), d.data(), P, mu * coeff.a, 1.0,
                                      [&](int i, int j, double v) {
                                          if (transposed)
                                              columns(3 * l + j, 3 * column + i) += v;
                                          else
                                              columns(3 * k + i, 3 * column + j) += v;
                                      });
                }
            }
        };
        // The pairs' integrals in parallel, then their blocks added in pair order (deterministic),
        // a chunk of pairs at a time: the coefficients of all pairs at once took 64 bytes a pair,
        // hundreds of MB at thousands of unknowns.
        constexpr std::size_t kChunk = std::size_t(1) << 16;
        std::vector<std::pair<int, int>> pairs;
        std::vector<PairCoefficients> coeffs(kChunk);
        pairs.reserve(kChunk);
        const auto addPairs = [&] {
            const int n = static_cast<int>(pairs.size());
#pragma omp parallel for schedule(dynamic, 64)
            for (int i = 0; i < n; ++i)
                coeffs[i] = coefficientsOf(
                    integrate(elements[pairs[i].first].panel, elements[pairs[i].second].panel, q, false), mu,
                    nu);
            for (int i = 0; i < n; ++i) {
                const auto [x, y] = pairs[i];
                addBlock(elements[x], elements[y], coeffs[i], false);
                if (y != x) addBlock(elements[x], elements[y], coeffs[i], true);
            }
            pairs.clear();
        };
        const int count = static_cast<int>(elements.size());
        for (int x = 0; x < count; ++x)
            for (int y = x; y < count; ++y)
                if (touchesRedo[x] || touchesRedo[y]) {
                    pairs.emplace_back(x, y);
                    if (pairs.size() == kChunk) addPairs();
                }
        addPairs();

        const double integrals = phase.seconds();
        // The blocks in unknown order, the redone unknowns' columns (and rows of G, D) replaced.
        // C enters only as L^-1 P C (K_R = L L^T).
        phase.restart();
        Eigen::MatrixXd whitened = solver_.factorSolve(coupling.C);
        if (blocks_ == Blocks::Keep)
            C_.conservativeResize(Eigen::NoChange, new3);
        else
            coupling.C = Eigen::MatrixXd();
        W_.conservativeResize(Eigen::NoChange, new3);
        Gt_.conservativeResize(Eigen::NoChange, new3);
        if (blocks_ == Blocks::Keep) D_.conservativeResize(new3, new3);
        for (int i = 0; i < static_cast<int>(redo.size()); ++i) {
            const int at = 3 * redo[i];
            W_.middleCols(at, 3) = whitened.middleCols(3 * i, 3);
            Gt_.middleCols(at, 3) = coupling.G.middleRows(3 * i, 3).transpose().cast<float>();
            if (blocks_ == Blocks::Keep) {
                C_.middleCols(at, 3) = coupling.C.middleCols(3 * i, 3);
                D_.middleCols(at, 3) = columns.middleCols(3 * i, 3);
                D_.middleRows(at, 3) = columns.middleCols(3 * i, 3).transpose();
            }
        }
        coupling.G = Eigen::MatrixXd();  // in Gt_ now: freed before the factor grows

        // Schur complement columns S(:, redo) = D(:, redo) - W^T W_redo, W = L^-1 P C (unknown order).
        columns -= transposedProduct(W_, whitened);
        whitened.resize(0, 0);
        coupling.C = Eigen::MatrixXd();
        const double schurColumns = phase.seconds();
        phase.restart();

        // S's columns of the redone unknowns, rows in the factor's new order.
        const int first3 = 3 * first, kept3 = 3 * kept;
        const bool wasDense = denseSchur_.size() > 0;
        Eigen::MatrixXd tail(new3, redo3);
        for (int r = 0; r < total; ++r) tail.middleRows(3 * r, 3) = columns.middleRows(3 * slots[r], 3);
        columns.resize(0, 0);
        // S in the new order, whole, for the LU: the kept block, then the redone columns.
        Eigen::MatrixXd grown;
        const auto growDense = [&](const Eigen::MatrixXd& keptBlock) {
            grown.resize(new3, new3);
            grown.topLeftCorner(kept3, kept3) = keptBlock;
            grown.rightCols(redo3) = tail;
            grown.bottomLeftCorner(redo3, kept3) = tail.topRows(kept3).transpose();
            for (int j = kept3; j < new3; ++j)  // the new block symmetric, from its lower triangle
                for (int i = kept3; i < j; ++i) grown(i, j) = grown(j, i);
        };
        // Taken over, not copied: the rows remove() replaces are freed before the new ones are
        // made (a copy would hold both: at 5,000 unknowns about 100 MB more). If this throws the
        // system is left empty (below). On LU, the factor is the Cholesky factor of S's leading
        // positive definite slots.
        BorderedCholesky factor = std::move(schur_);
        schur_ = BorderedCholesky();
        factorTaken = true;
        bool dense = wasDense;
        int indefiniteRows = indefiniteRows_;
        if (!dense) {
            std::vector<int> removed;
            for (int i = 0; i < changed; ++i)
                for (int d = 0; d < 3; ++d) removed.push_back(3 * slotOf[redo[i]] + d);
            std::sort(removed.begin(), removed.end());
            factor.remove(removed);
            if (!factor.extend(tail, 1e-15)) {
                indefiniteRows = new3;
                logf(luLogged_ ? LogLevel::Debug : LogLevel::Info, "crack system: the Schur complement of ",
                     total, " crack unknowns is not positive definite; factored by LU from here on");
                luLogged_ = true;
                dense = true;
                growDense(factor.product());
            }
        } else {
            growDense(denseSchur_(keptRows, keptRows));
            denseSchur_.resize(0, 0);  // in `grown` now; a throw below empties the system anyway
            factor.truncate(first3);
            // Back to Cholesky after a change if the kept part allows it: not while the kept rows
            // still hold, unchanged, the block whose extension failed (a principal block of a
            // matrix that is not positive definite is not either).
            if (changed > 0 && first3 < indefiniteRows) {
                if (!factor.extend(grown.block(0, factor.size(), kept3, kept3 - factor.size()), 1e-15))
                    indefiniteRows = kept3;
                else if (!factor.extend(tail, 1e-15))
                    indefiniteRows = new3;
                else
                    dense = false;
            }
        }
        if (dense) {
            // The LU extended from its last block boundary among the kept slots in blocks of
            // kLuBlock rows (so that a later change keeps the blocks before it); factored anew in
            // one block when a block is singular or the block pivoting lost accuracy.
            const double norm1 = grown.cwiseAbs().colwise().sum().maxCoeff();
            const auto factorFrom = [&grown, norm1, new3](BorderedLU& f, int block) {
                double smallest = std::numeric_limits<double>::infinity();
                for (int r = f.size(); r < new3; r = f.size()) {
                    const int h = std::min(block, new3 - r);
                    const double rcond =
                        f.extend(grown.block(0, r, r + h, h), grown.block(r, 0, h, r), norm1, kMinimumRcond);
                    if (!(rcond > kMinimumRcond)) return rcond;  // not extended
                    smallest = std::min(smallest, rcond);
                }
                return smallest;
            };
            BorderedLU lu = wasDense ? std::move(lu_) : BorderedLU();  // taken over, as the factor
            lu.truncate(first3);
            double rcond = factorFrom(lu, kLuBlock);
            if (!(rcond > kMinimumRcond && probeBackwardError(lu, grown) <= 1e-11)) {
                lu = BorderedLU();
                rcond = factorFrom(lu, new3);
            }
            if (!(rcond > kMinimumRcond))
                throw Error("crack system: the Schur complement of " + std::to_string(total) +
                            " crack unknowns is singular (reciprocal condition " + scientific(rcond) +
                            "); the crack mesh is probably degenerate (slivers, overlapping sheets)");
            denseSchur_ = std::move(grown);
            lu_ = std::move(lu);
        } else {
            denseSchur_.resize(0, 0);
            lu_ = BorderedLU();
        }
        logf(LogLevel::Debug, "crack system: ", total, " crack unknowns, ", redo.size(),
             " assembled: integrals ", integrals, " s, Schur complement columns ", schurColumns,
             " s, factor ", phase.seconds(), " s");
        schur_ = std::move(factor);
        indefiniteRows_ = dense ? indefiniteRows : 0;
        slots_ = std::move(slots);
        fingerprints_ = std::move(fingerprints);
        assembledUnknowns_ = total;
    } catch (const Error&) {
        if (factorTaken) {  // the old factor is gone: empty, for the next update() to assemble anew
            W_.resize(W_.rows(), 0);
            if (blocks_ == Blocks::Keep) C_.resize(C_.rows(), 0);
            Gt_.resize(Gt_.rows(), 0);
            D_.resize(0, 0);
            denseSchur_.resize(0, 0);
            lu_ = BorderedLU();
            indefiniteRows_ = 0;
            slots_.clear();
            fingerprints_.clear();
            assembledUnknowns_ = 0;
            throw;
        }
        for (int i = 0; i < changed; ++i) {
            W_.middleCols(3 * redo[i], 3) = savedW.middleCols(3 * i, 3);
            Gt_.middleCols(3 * redo[i], 3) = savedG.middleCols(3 * i, 3);
            if (blocks_ == Blocks::Keep) {
                C_.middleCols(3 * redo[i], 3) = savedC.middleCols(3 * i, 3);
                D_.middleCols(3 * redo[i], 3) = savedD.middleCols(3 * i, 3);
                D_.middleRows(3 * redo[i], 3) = savedD.middleCols(3 * i, 3).transpose();
            }
        }
        W_.conservativeResize(Eigen::NoChange, 3 * assembledUnknowns_);
        if (blocks_ == Blocks::Keep) C_.conservativeResize(Eigen::NoChange, 3 * assembledUnknowns_);
        Gt_.conservativeResize(Eigen::NoChange, 3 * assembledUnknowns_);
        if (blocks_ == Blocks::Keep) D_.conservativeResize(3 * assembledUnknowns_, 3 * assembledUnknowns_);
        throw;
    }
    return total - before;
}

CrackSystem::Solution CrackSystem::solve(const Eigen::VectorXd& q) const {
    return solve(q, solver_.displacements(q));
}

CrackSystem::Solution CrackSystem::solve(const Eigen::VectorXd& q, const Eigen::VectorXd& b) const {
    Solution s;
    if (b.size() != 3 * solver_.mesh().nodeCount())
        throw Error("CrackSystem::solve: expected " + std::to_string(3 * solver_.mesh().nodeCount()) +
                    " crack-free displacement values, got " + std::to_string(b.size()));
    if (assembledUnknowns_ == 0) {
        s.displacements = b;
        s.openings.resize(0);
        return s;
    }
    // (P C)^T b = W^T L^T b.
    const Eigen::VectorXd rhs = loadOnCracks(q) - transposedTimes(W_, solver_.factorTransposeTimes(b));
    Eigen::VectorXd x(rhs.size());  // in the factor's order
    for (int k = 0; k < assembledUnknowns_; ++k) x.segment<3>(3 * k) = rhs.segment<3>(3 * slots_[k]);
    if (denseSchur_.size() > 0) {
        const Eigen::VectorXd ordered = x;
        lu_.solveInPlace(x);
        // Normwise backward error: the LU passed a probe solve at 1e-11, so only a broken solve
        // exceeds it (the residual relative to the load alone grows with S's condition near
        // separation).
        const double residual = backwardError(denseSchur_, x, ordered);
        if (!(residual <= 1e-10))
            throw Error("crack system: Schur complement solve failed (backward error " +
                        scientific(residual) + "); the crack mesh is probably degenerate");
    } else {
        schur_.solveInPlace(x);
    }
    s.openings.resize(rhs.size());
    for (int k = 0; k < assembledUnknowns_; ++k) s.openings.segment<3>(3 * slots_[k]) = x.segment<3>(3 * k);
    if (!s.openings.allFinite())
        throw Error(
            "crack system: the Schur complement solve gave NaN or Inf; the crack mesh is probably "
            "degenerate");
    s.displacements = b - solver_.factorTransposeSolve(W_ * s.openings);
    solver_.fixGauge(s.displacements);
    return s;
}

CrackSystem::Solution CrackSystem::solveMonolithic(const Eigen::VectorXd& q) const {
    const Eigen::MatrixXd& D = crackCrackBlock();
    const Eigen::MatrixXd K = solver_.stiffness();
    const int n3 = static_cast<int>(K.rows()), k3 = 3 * assembledUnknowns_;
    const Eigen::MatrixXd& Q = solver_.rigidBasis();
    const Eigen::MatrixXd PC = solver_.withoutRigidMotions(surfaceCrackBlock());
    Eigen::MatrixXd A(n3 + k3, n3 + k3);
    A.topLeftCorner(n3, n3) = K + solver_.regularisationWeight() * Q * Q.transpose();
    A.topRightCorner(n3, k3) = PC;
    A.bottomLeftCorner(k3, n3) = PC.transpose();
    A.bottomRightCorner(k3, k3) = D;
    Eigen::VectorXd rhs(n3 + k3);
    rhs.head(n3) = solver_.withoutRigidMotions(solver_.load(q));
    rhs.tail(k3) = loadOnCracks(q);
    const Eigen::VectorXd x = A.partialPivLu().solve(rhs);
    Eigen::VectorXd u = x.head(n3);
    solver_.fixGauge(u);
    return {u, x.tail(k3)};
}

Eigen::VectorXd CrackSystem::loadOnCracks(const Eigen::VectorXd& q) const {
    return productInDouble(Gt_.transpose(), q);
}

std::size_t CrackSystem::matrixBytes() const {
    return sizeof(double) * (W_.size() + C_.size() + D_.size() + denseSchur_.size()) +
           sizeof(float) * Gt_.size() + schur_.bytes() + lu_.bytes();
}

Eigen::VectorXd CrackSystem::nodalOpenings(const Solution& s) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(3 * cracks_.nodeCount());
    for (int k = 0; k < assembledUnknowns_; ++k)
        out.segment<3>(3 * cracks_.nodeOfUnknown()[k]) = s.openings.segment<3>(3 * k);
    return out;
}

}  // namespace btfracture
