// SPDX-License-Identifier: Zlib
#pragma once
// A body's elastostatic system with cracks (paper Eq. 4): surface displacements u and crack
// opening displacements (COD), solved by the Schur complement on the prefactored K_R, which is
// never rebuilt when cracks change:
//   [ K_R    K^T C ] [ u   ]   [ K^T F q ]
//   [ C^T    D     ] [ cod ] = [ G q     ]
// C couples surface and crack hats, D crack hats with each other (appendix Eq. 8), G q is the
// traction that the surface loads q induce on the crack faces through the adjoint double layer
// (zero only for cracks far from any loaded surface). Blocks, and the Schur complement
// S = D - C^T H, are extended incrementally: when a crack grows, only the rows and columns of the
// new unknowns are computed.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/ElasticSolver.h>

#include <Eigen/Core>

namespace btfracture {

class CrackSystem {
public:
    // Borrows `solver` and `cracks`, which must outlive this object. Unknowns the crack mesh
    // already has are assembled by the first update().
    CrackSystem(const ElasticSolver& solver, CrackMesh& cracks);

    CrackMesh& cracks() { return cracks_; }
    const CrackMesh& cracks() const { return cracks_; }
    const ElasticSolver& solver() const { return solver_; }

    // Numbers the unknowns of nodes that left the front and assembles their rows and columns.
    // Returns the number of new unknown nodes.
    int update();

    struct Solution {
        Eigen::VectorXd displacements;  // u, 3n [m]
        Eigen::VectorXd openings;       // COD per crack unknown, 3k [m]
    };
    // Schur complement solve (P0 tractions q, 3m [Pa], balanced).
    Solution solve(const Eigen::VectorXd& tractions) const;
    // The same system factored as a whole (for tests; O((3n + 3k)^3)).
    Solution solveMonolithic(const Eigen::VectorXd& tractions) const;

    // COD at every crack node (zero on the front), 3 x nodeCount.
    Eigen::VectorXd nodalOpenings(const Solution& s) const;

    const Eigen::MatrixXd& surfaceCrackBlock() const { return C_; }  // 3n x 3k
    const Eigen::MatrixXd& crackCrackBlock() const { return D_; }    // 3k x 3k
    const Eigen::MatrixXd& crackLoadBlock() const { return G_; }     // 3k x 3m

private:
    const ElasticSolver& solver_;
    CrackMesh& cracks_;
    Eigen::MatrixXd C_, D_, G_, H_;  // H = K_R^-1 K^T C
    Eigen::MatrixXd schur_;          // D - C^T H, 3k x 3k
    int assembledUnknowns_ = 0;
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
