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
    Eigen::MatrixXd out(a.cols(), b.cols());
    forEachColumnBlock(b.cols(), 64, [&](int j0, int w) {
        out.middleCols(j0, w).noalias() = a.transpose() * b.middleCols(j0, w);
    });
    return out;
}

}  // namespace btfracture
