// SPDX-License-Identifier: Zlib
#pragma once
// Dense products and solves on all cores whose result does not depend on the thread count.
// Eigen's own OpenMP products choose their blocking (and so their rounding) by the number of
// threads; the library turns them off (EIGEN_DONT_PARALLELIZE, btFracture/CMakeLists.txt) and
// cuts the result into column blocks of a fixed width instead, each computed by Eigen on one
// thread.
#include <Eigen/Core>

#include <algorithm>

namespace btfracture {

// Calls work(first, count) for the blocks of `width` columns (the last one narrower) of a matrix
// with `columns` columns, on all cores when there is more than one block.
template <class Work>
void forEachColumnBlock(Eigen::Index columns, int width, Work&& work) {
    const int n = static_cast<int>(columns);
#pragma omp parallel for schedule(dynamic, 1) if (n > width)
    for (int j0 = 0; j0 < n; j0 += width) work(j0, std::min(width, n - j0));
}

// a q for a matrix a kept in single precision because it only ever forms this product, summed in
// double a few rows at a time (the whole of a in double would be a temporary twice its size), the
// blocks of rows on all cores. Each entry is a dot product of its own row: the same bits for any
// block size and thread count.
template <class Float>
Eigen::VectorXd productInDouble(const Eigen::MatrixBase<Float>& a, const Eigen::VectorXd& q) {
    constexpr int kRows = 64;
    const int rows = static_cast<int>(a.rows());
    Eigen::VectorXd out(rows);
#pragma omp parallel for schedule(static) if (rows > 4 * kRows)
    for (int r = 0; r < rows; r += kRows) {
        const int h = std::min(kRows, rows - r);
        out.segment(r, h).noalias() = a.middleRows(r, h).template cast<double>() * q;
    }
    return out;
}

// a^T x on all cores, in blocks of 64 columns of a: Eigen's row-major kernel takes rows eight at a
// time from the first, so every entry rounds as in the single product a^T x.
Eigen::VectorXd transposedTimes(const Eigen::MatrixXd& a, const Eigen::VectorXd& x);

// a^T b for a (k x m) and b (k x n): an m x n matrix, in fixed blocks of rows and columns.
Eigen::MatrixXd transposedProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b);

}  // namespace btfracture
