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
    // Blocks of kRows rows (the last one up to twice that) by 64 columns. Eigen packs the whole
    // left operand for every product, which made a^T b for a few columns of b several times
    // slower than in row blocks. Every block still goes through Eigen's blocked kernel; in the
    // portable build its entries round as in a product of the whole 64 columns (3,120 shapes
    // checked), under -march=native they may not. Either way the grid is fixed: the result does
    // not depend on the thread count.
    constexpr int kRows = 256, kColumns = 64;
    const int m = static_cast<int>(a.cols()), n = static_cast<int>(b.cols());
    const int rowBlocks = std::max(1, m / kRows), columnBlocks = (n + kColumns - 1) / kColumns;
    Eigen::MatrixXd out(m, n);
#pragma omp parallel for schedule(dynamic, 1) if (rowBlocks * columnBlocks > 1)
    for (int block = 0; block < rowBlocks * columnBlocks; ++block) {
        const int i0 = (block % rowBlocks) * kRows, j0 = (block / rowBlocks) * kColumns;
        const int h = i0 + kRows * 2 > m ? m - i0 : kRows, w = std::min(kColumns, n - j0);
        out.block(i0, j0, h, w).noalias() = a.middleCols(i0, h).transpose() * b.middleCols(j0, w);
    }
    return out;
}

Eigen::VectorXd transposedTimes(const Eigen::MatrixXd& a, const Eigen::VectorXd& x) {
    if (a.rows() != x.size())
        throw Error("transposedTimes: " + std::to_string(a.rows()) + " rows against " +
                    std::to_string(x.size()));
    constexpr int kColumns = 64;  // a multiple of 8 (the kernel's row block)
    const int m = static_cast<int>(a.cols());
    Eigen::VectorXd out(m);
#pragma omp parallel for schedule(static) if (m > 4 * kColumns)
    for (int j = 0; j < m; j += kColumns) {
        const int w = std::min(kColumns, m - j);
        out.segment(j, w).noalias() = a.middleCols(j, w).transpose() * x;
    }
    return out;
}

}  // namespace btfracture
