// SPDX-License-Identifier: Zlib
#pragma once
// A body's elastostatic system with cracks (paper Eq. 4): surface displacements u and crack
// opening displacements (COD), solved by the Schur complement on the prefactored K_R = L L^T,
// which is never rebuilt when cracks change:
//   [ K_R    P C ] [ u   ]   [ P F q ]
//   [ C^T P  D   ] [ cod ] = [ G q   ]
// C couples surface and crack hats, D crack hats with each other (appendix Eq. 8), G q is the
// traction that the surface loads q induce on the crack faces through the adjoint double layer
// (zero only for cracks far from any loaded surface); P projects off the rigid motions
// (ElasticSolver). C is kept as W = L^-1 P C, so S = D - W^T W is symmetric by construction and
// positive definite up to rounding; it is factored by Cholesky from its columns S(:, new) =
// D(:, new) - W^T W_new. When a crack grows, only the new unknowns' columns are computed and the
// factor is extended by bordering (BorderedCholesky): D is folded into it and freed. Unknowns
// whose basis function a changed mouth cut alters are assembled again: they leave the factor by
// rank-one updates and join it again last. A system
// whose S is not numerically positive definite (crack nodes just under the surface, sheets that
// nearly cut a body through) is factored by LU from then on (logged), S held in full and the LU extended
// block by block as it grows (BorderedLU; factored anew in one block when the block pivoting loses accuracy).
#include <btFracture/bem/BorderedCholesky.h>
#include <btFracture/bem/BorderedLU.h>
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/ElasticSolver.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace btfracture {

class CrackSystem {
public:
    // Keep: D is kept besides the factor (for crackCrackBlock and solveMonolithic, in tests).
    enum class Blocks { Fold, Keep };
    // Borrows `solver` and `cracks`, which must outlive this object. Unknowns the crack mesh
    // already has are assembled by the first update().
    CrackSystem(const ElasticSolver& solver, CrackMesh& cracks, Blocks blocks = Blocks::Fold);

    CrackMesh& cracks() { return cracks_; }
    const CrackMesh& cracks() const { return cracks_; }
    const ElasticSolver& solver() const { return solver_; }

    // Numbers the unknowns of nodes that left the front and assembles their rows and columns.
    // Returns the number of new unknown nodes. Throws btfracture::Error when the grown Schur
    // complement is singular (a degenerate crack mesh), leaving the system empty: solve() then
    // sees no crack unknowns, and the next update() assembles all of them again.
    int update();

    struct Solution {
        Eigen::VectorXd displacements;  // u, 3n [m]
        Eigen::VectorXd openings;       // COD per crack unknown, 3k [m]
    };
    // Schur complement solve (P0 tractions q, 3m [Pa], balanced).
    Solution solve(const Eigen::VectorXd& tractions) const;
    // The same, given the crack-free displacements of q (ElasticSolver::displacements): a caller
    // that solves one load as the cracks grow forms F q and its surface solve once.
    Solution solve(const Eigen::VectorXd& tractions, const Eigen::VectorXd& crackFree) const;
    // The same system factored as a whole (Blocks::Keep only; O((3n + 3k)^3)).
    Solution solveMonolithic(const Eigen::VectorXd& tractions) const;

    // COD at every crack node (zero on the front), 3 x nodeCount.
    Eigen::VectorXd nodalOpenings(const Solution& s) const;

    // C (3n x 3k), Blocks::Keep only.
    const Eigen::MatrixXd& surfaceCrackBlock() const;
    // P C w (3n): the surface load of openings w (3k), P the projection off the rigid motions.
    Eigen::VectorXd surfaceLoadOf(const Eigen::VectorXd& openings) const;
    const Eigen::MatrixXd& crackCrackBlock() const;  // 3k x 3k, Blocks::Keep only
    // Bytes held by the crack blocks and the factor (the ElasticSolver's not included).
    std::size_t matrixBytes() const;

private:
    const ElasticSolver& solver_;
    CrackMesh& cracks_;
    const Blocks blocks_;
    Eigen::MatrixXd W_;      // L^-1 P C (3n x 3k), K_R = L L^T (ElasticSolver)
    Eigen::MatrixXd C_, D_;  // Blocks::Keep only
    // G^T (3m x 3k: grows by columns, in place), single precision (half the bytes of the largest
    // block): G only forms the right-hand side G q, in double, so the rounding stays near 1e-7 of it.
    Eigen::MatrixXf Gt_;
    Eigen::VectorXd loadOnCracks(const Eigen::VectorXd& tractions) const;  // G q
    BorderedCholesky schur_;      // S = D - W^T W; on LU, of S's leading positive definite slots
    Eigen::MatrixXd denseSchur_;  // S in full, once Cholesky failed
    BorderedLU lu_;               // its LU, grown with it
    int indefiniteRows_ = 0;      // on LU: S's leading rows (factor order) known not positive definite
    int assembledUnknowns_ = 0;
    // The factor's order (slot -> crack unknown): C, D and G are in unknown order.
    std::vector<int> slots_;
    std::vector<std::uint64_t> fingerprints_;  // per assembled unknown: its basis function's hash
    bool luLogged_ = false;                    // the LU fallback is logged as info once, then as debug
    int unfollowedEdges_ = 0;  // the most mouth edges left out of a cut so far (logged when it grows)
};

// Columns of C for the given crack unknowns and the matching rows of G, computed from scratch
// (used by CrackSystem::update and by the estimator's matrix-free right-hand-side update, §4.3,
// which needs C alone: G is then left empty and its double-layer integrals are skipped).
struct CrackSurfaceCoupling {
    Eigen::MatrixXd C;  // 3n x 3 unknowns
    Eigen::MatrixXd G;  // 3 unknowns x 3m, or empty
};
enum class CouplingBlocks { SurfaceAndLoad, SurfaceOnly };
CrackSurfaceCoupling assembleCrackSurfaceCoupling(const ElasticSolver& solver, const CrackMesh& cracks,
                                                  const std::vector<int>& unknowns,
                                                  CouplingBlocks blocks = CouplingBlocks::SurfaceAndLoad);

}  // namespace btfracture
