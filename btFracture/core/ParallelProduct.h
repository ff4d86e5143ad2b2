// SPDX-License-Identifier: Zlib
#pragma once
// Dense products on all cores whose result does not depend on the thread count. Eigen's own
// OpenMP products choose their blocking (and so their rounding) by the number of threads; the
// library turns them off (EIGEN_DONT_PARALLELIZE, btFracture/CMakeLists.txt) and cuts the result
// into column blocks of a fixed width instead, each computed by Eigen on one thread.
#include <Eigen/Core>

namespace btfracture {

// a^T b for a (k x m) and b (k x n): an m x n matrix.
Eigen::MatrixXd transposedProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b);

}  // namespace btfracture
