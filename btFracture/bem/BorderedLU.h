// SPDX-License-Identifier: Zlib
#pragma once
// LU factors P S = L U of a square matrix that grows by whole blocks of rows and columns while
// its old entries keep their values (CrackSystem's Schur complement once it is not positive
// definite). Bordering: for S' = [S B; R E],
//   P' = diag(P, Q),  L' = [L 0; Q X  L_E],  U' = [U Y; 0 U_E],
//   Y = L^-1 P B,  X = R U^-1,  Q (E - X Y) = L_E U_E  (partial pivoting within the new block),
// so a block of h rows costs O(n^2 h) instead of a new O(n^3) factorisation. Pivoting never
// crosses a block boundary, which is weaker than partial pivoting over the whole matrix: callers
// check a solve's backward error and factor anew in one block when it is not small.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace btfracture {

class BorderedLU {
public:
    int size() const { return static_cast<int>(permutation_.size()); }

    // Extends the factors by the grown matrix's new columns [B; E] (size() + h rows, h columns)
    // and new rows R (h x size()); `grownNorm1` is the grown matrix's 1-norm. Returns an estimate
    // of 1 / (||S'||_1 ||(E - X Y)^-1||_1), which bounds S''s reciprocal condition number from
    // above (the inverse of E - X Y is a block of S'^-1); when it is not above `minimumRcond`
    // the factors are left as they were.
    double extend(const Eigen::Ref<const Eigen::MatrixXd>& columns,
                  const Eigen::Ref<const Eigen::MatrixXd>& rows, double grownNorm1, double minimumRcond);

    // Keeps the factors of the leading blocks that end at or before `rows`; returns their size.
    int truncate(int rows);

    // x := S^-1 x.
    void solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const;

    int blocks() const { return static_cast<int>(blockStarts_.size()); }
    std::size_t bytes() const;

private:
    Eigen::MatrixXd lu_;            // L below the diagonal (unit diagonal implied), U on and above
    std::vector<int> permutation_;  // row k of P S is row permutation_[k] of S
    std::vector<int> blockStarts_;  // first row of each block
};

}  // namespace btfracture
