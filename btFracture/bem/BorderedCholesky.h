// SPDX-License-Identifier: Zlib
#pragma once
// Cholesky factor L (S = L L^T) of a symmetric positive definite matrix that grows by whole
// blocks of rows and columns while its old entries keep their values (the crack Schur complement
// of CrackSystem as cracks grow). Bordering: for S' = [S B; B^T E],
//   L' = [L 0; X^T M],  X = L^-1 B,  M M^T = E - X^T X,
// so growing to N unknowns in any number of steps costs N^3 / 3 flops in all, as one
// factorisation would. Rows are stored in one panel per extension (lower triangle only: about
// half the memory of a square matrix). Results do not depend on the thread count.
#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace btfracture {

class BorderedCholesky {
public:
    int size() const { return size_; }

    // Extends the factor by the columns [B; E] (size() + h rows, h columns) of the grown matrix;
    // only E's lower triangle is read. Returns false, and leaves the factor as it was, when the
    // grown matrix is not numerically positive definite or its diagonalRatio() would fall below
    // `minimumDiagonalRatio`.
    bool extend(const Eigen::Ref<const Eigen::MatrixXd>& columns, double minimumDiagonalRatio = 0.0);

    // Keeps the factor of the leading `rows` x `rows` block only (rows <= size()).
    void truncate(int rows);

    // The factor of S without the given rows and columns (indices into S, ascending, distinct):
    // deleting index j leaves the factor's rows above j as they are and turns the trailing factor
    // into that of L22 L22^T + l l^T (l: column j below the diagonal), a rank-one update by
    // rotations, so deleting d of the last m indices costs about 2 d m^2 flops instead of
    // refactoring them.
    void remove(const std::vector<int>& indices);

    // x := L^-1 x for size() rows and any number of columns.
    void forwardSubstitute(Eigen::Ref<Eigen::MatrixXd> x) const;
    // x := S^-1 x.
    void solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const;

    // (min_i L_ii / max_i L_ii)^2, an upper bound on S's reciprocal condition number (each L_ii^2
    // lies between S's extreme eigenvalues); 1 while empty.
    double diagonalRatio() const;
    // S = L L^T as a dense matrix (size() x size()).
    Eigen::MatrixXd product() const;
    std::size_t bytes() const;

private:
    struct Panel {
        int row0;           // first row of the panel
        Eigen::MatrixXd L;  // rows row0 .. row0 + h of L: [X^T | M], M lower triangular
    };
    // Panels never change once made (truncate and remove make new ones), so a copy of the factor
    // shares them: copying costs nothing, changing a copy leaves the original as it was.
    std::vector<std::shared_ptr<const Panel>> panels_;
    int size_ = 0;
    double minDiagonal_ = 0.0, maxDiagonal_ = 0.0;
};

}  // namespace btfracture
