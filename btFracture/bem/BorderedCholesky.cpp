// SPDX-License-Identifier: Zlib
#include <btFracture/bem/BorderedCholesky.h>

#include <btFracture/core/ParallelProduct.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace btfracture {

bool BorderedCholesky::extend(const Eigen::Ref<const Eigen::MatrixXd>& columns, double minimumDiagonalRatio) {
    const int h = static_cast<int>(columns.cols());
    if (h == 0) return true;
    Eigen::MatrixXd X = columns.topRows(size_);
    forwardSubstitute(X);
    Eigen::MatrixXd E = columns.bottomRows(h);
    if (size_ > 0) E -= transposedProduct(X, X);
    const Eigen::MatrixXd lower = E.triangularView<Eigen::Lower>();
    E = lower + lower.transpose();
    E.diagonal() *= 0.5;
    Eigen::LLT<Eigen::MatrixXd> llt(E);
    if (llt.info() != Eigen::Success) return false;
    const Eigen::VectorXd d = llt.matrixLLT().diagonal();
    if (!d.allFinite() || d.minCoeff() <= 0.0) return false;
    const double lo = size_ == 0 ? d.minCoeff() : std::min(minDiagonal_, d.minCoeff());
    const double hi = size_ == 0 ? d.maxCoeff() : std::max(maxDiagonal_, d.maxCoeff());
    if ((lo / hi) * (lo / hi) < minimumDiagonalRatio) return false;
    Panel panel{size_, Eigen::MatrixXd(h, size_ + h)};
    panel.L.leftCols(size_) = X.transpose();
    panel.L.rightCols(h) = llt.matrixL();
    panels_.push_back(std::move(panel));
    minDiagonal_ = lo;
    maxDiagonal_ = hi;
    size_ += h;
    return true;
}

void BorderedCholesky::forwardSubstitute(Eigen::Ref<Eigen::MatrixXd> x) const {
    forEachColumnBlock(x.cols(), 32, [&](int j0, int w) {
        auto xs = x.middleCols(j0, w);
        for (const Panel& p : panels_) {
            const int h = static_cast<int>(p.L.rows());
            if (p.row0 > 0) xs.middleRows(p.row0, h).noalias() -= p.L.leftCols(p.row0) * xs.topRows(p.row0);
            p.L.rightCols(h).triangularView<Eigen::Lower>().solveInPlace(xs.middleRows(p.row0, h));
        }
    });
}

void BorderedCholesky::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const {
    forwardSubstitute(x);
    for (auto p = panels_.rbegin(); p != panels_.rend(); ++p) {
        const int h = static_cast<int>(p->L.rows());
        auto xp = x.segment(p->row0, h);
        p->L.rightCols(h).triangularView<Eigen::Lower>().transpose().solveInPlace(xp);
        if (p->row0 > 0) x.head(p->row0).noalias() -= p->L.leftCols(p->row0).transpose() * xp;
    }
}

void BorderedCholesky::truncate(int rows) {
    if (rows >= size_) return;
    while (!panels_.empty() && panels_.back().row0 >= rows) panels_.pop_back();
    if (!panels_.empty()) {
        Panel& p = panels_.back();
        const int keep = rows - p.row0;
        if (keep < p.L.rows()) p.L = p.L.topLeftCorner(keep, p.row0 + keep).eval();
    }
    size_ = rows;
    minDiagonal_ = std::numeric_limits<double>::infinity();
    maxDiagonal_ = 0.0;
    for (const Panel& p : panels_)
        for (int i = 0; i < p.L.rows(); ++i) {
            minDiagonal_ = std::min(minDiagonal_, p.L(i, p.row0 + i));
            maxDiagonal_ = std::max(maxDiagonal_, p.L(i, p.row0 + i));
        }
}

double BorderedCholesky::diagonalRatio() const {
    return size_ == 0 ? 1.0 : (minDiagonal_ / maxDiagonal_) * (minDiagonal_ / maxDiagonal_);
}

Eigen::MatrixXd BorderedCholesky::product() const {
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(size_, size_);
    for (const Panel& p : panels_) L.block(p.row0, 0, p.L.rows(), p.L.cols()) = p.L;
    return transposedProduct(L.transpose(), L.transpose());
}

Eigen::MatrixXd BorderedCholesky::productColumns(int first, int count) const {
    // S(:, J) = L L(J, :)^T with J = first .. first + count.
    Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(count, size_);
    for (const Panel& p : panels_) {
        const int h = static_cast<int>(p.L.rows());
        const int lo = std::max(first, p.row0), hi = std::min(first + count, p.row0 + h);
        if (lo < hi) rows.block(lo - first, 0, hi - lo, p.L.cols()) = p.L.middleRows(lo - p.row0, hi - lo);
    }
    Eigen::MatrixXd out(size_, count);
    for (const Panel& p : panels_)
        out.middleRows(p.row0, p.L.rows()).noalias() = p.L * rows.leftCols(p.L.cols()).transpose();
    return out;
}

std::size_t BorderedCholesky::bytes() const {
    std::size_t out = 0;
    for (const Panel& p : panels_) out += sizeof(double) * p.L.size();
    return out;
}

}  // namespace btfracture
