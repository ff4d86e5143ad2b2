// SPDX-License-Identifier: Zlib
#include <btFracture/bem/BorderedLU.h>

#include <Eigen/LU>

namespace btfracture {

double BorderedLU::extend(const Eigen::Ref<const Eigen::MatrixXd>& columns,
                          const Eigen::Ref<const Eigen::MatrixXd>& rows, double grownNorm1,
                          double minimumRcond) {
    const int n = size(), h = static_cast<int>(columns.cols());
    if (h == 0) return 1.0;
    Eigen::MatrixXd Y(n, h);  // L^-1 P B
    for (int k = 0; k < n; ++k) Y.row(k) = columns.row(permutation_[k]);
    Eigen::MatrixXd Xt = rows.transpose();  // (R U^-1)^T = U^-T R^T
    if (n > 0) {
        lu_.triangularView<Eigen::UnitLower>().solveInPlace(Y);
        lu_.triangularView<Eigen::Upper>().transpose().solveInPlace(Xt);
    }
    Eigen::MatrixXd E = columns.bottomRows(h);
    if (n > 0) E.noalias() -= Xt.transpose() * Y;
    const Eigen::PartialPivLU<Eigen::MatrixXd> block(E);
    const double rcond = block.rcond() * E.cwiseAbs().colwise().sum().maxCoeff() / grownNorm1;
    if (!(rcond > minimumRcond) || !block.matrixLU().allFinite()) return rcond;

    const Eigen::VectorXi order = block.permutationP() * Eigen::VectorXi::LinSpaced(h, 0, h - 1);
    lu_.conservativeResize(n + h, n + h);
    lu_.topRightCorner(n, h) = Y;
    lu_.bottomLeftCorner(h, n) = block.permutationP() * Xt.transpose();
    lu_.bottomRightCorner(h, h) = block.matrixLU();
    blockStarts_.push_back(n);
    for (int k = 0; k < h; ++k) permutation_.push_back(n + order[k]);
    return rcond;
}

int BorderedLU::truncate(int rows) {
    if (rows >= size()) return size();
    int kept = 0;  // the last block boundary at or before `rows`
    for (const int start : blockStarts_)
        if (start <= rows) kept = start;
    while (!blockStarts_.empty() && blockStarts_.back() >= kept) blockStarts_.pop_back();
    lu_ = lu_.topLeftCorner(kept, kept).eval();
    permutation_.resize(static_cast<std::size_t>(kept));
    return kept;
}

void BorderedLU::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const {
    Eigen::VectorXd y(size());
    for (int k = 0; k < size(); ++k) y[k] = x[permutation_[k]];
    lu_.triangularView<Eigen::UnitLower>().solveInPlace(y);
    lu_.triangularView<Eigen::Upper>().solveInPlace(y);
    x = y;
}

std::size_t BorderedLU::bytes() const {
    return sizeof(double) * static_cast<std::size_t>(lu_.size()) + sizeof(int) * permutation_.size();
}

}  // namespace btfracture
