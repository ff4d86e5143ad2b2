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

// a^T b for a (k x m) and b (k x n): an m x n matrix.
Eigen::MatrixXd transposedProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b);

}  // namespace btfracture
