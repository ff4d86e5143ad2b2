// SPDX-License-Identifier: Zlib
#include <btFracture/core/ParallelProduct.h>

#include <btFracture/core/Error.h>

#include <algorithm>
#include <string>

namespace btfracture {

Eigen::MatrixXd transposedProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b) {
    if (a.rows() != b.rows())
        throw Error("transposedProduct: " + std::to_string(a.rows()) + " rows against " +
                    std::to_string(b.rows()));
    constexpr int kBlock = 64;  // columns per task: fixed, so the result is the same on any core count
    const int n = static_cast<int>(b.cols());
    Eigen::MatrixXd out(a.cols(), b.cols());
#pragma omp parallel for schedule(dynamic, 1)
    for (int j0 = 0; j0 < n; j0 += kBlock) {
        const int w = std::min(kBlock, n - j0);
        out.middleCols(j0, w).noalias() = a.transpose() * b.middleCols(j0, w);
    }
    return out;
}

}  // namespace btfracture
