// SPDX-License-Identifier: Zlib
#include <btFracture/bem/BorderedCholesky.h>

#include <btFracture/core/ParallelProduct.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace btfracture {

namespace {
constexpr int kRemovedPanelRows = 192;  // rows per panel of a factor's part rebuilt by remove()
}  // namespace

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
    auto panel = std::make_shared<Panel>(Panel{size_, Eigen::MatrixXd(h, size_ + h)});
    panel->L.leftCols(size_) = X.transpose();
    panel->L.rightCols(h) = llt.matrixL();
    panels_.push_back(std::move(panel));
    minDiagonal_ = lo;
    maxDiagonal_ = hi;
    size_ += h;
    return true;
}

void BorderedCholesky::forwardSubstitute(Eigen::Ref<Eigen::MatrixXd> x) const {
    forEachColumnBlock(x.cols(), 32, [&](int j0, int w) {
        auto xs = x.middleCols(j0, w);
        for (const auto& panel : panels_) {
            const Panel& p = *panel;
            const int h = static_cast<int>(p.L.rows());
            if (p.row0 > 0) xs.middleRows(p.row0, h).noalias() -= p.L.leftCols(p.row0) * xs.topRows(p.row0);
            p.L.rightCols(h).triangularView<Eigen::Lower>().solveInPlace(xs.middleRows(p.row0, h));
        }
    });
}

void BorderedCholesky::solveInPlace(Eigen::Ref<Eigen::VectorXd> x) const {
    forwardSubstitute(x);
    for (auto it = panels_.rbegin(); it != panels_.rend(); ++it) {
        const Panel* p = it->get();
        const int h = static_cast<int>(p->L.rows());
        auto xp = x.segment(p->row0, h);
        p->L.rightCols(h).triangularView<Eigen::Lower>().transpose().solveInPlace(xp);
        if (p->row0 > 0) x.head(p->row0).noalias() -= p->L.leftCols(p->row0).transpose() * xp;
    }
}

void BorderedCholesky::truncate(int rows) {
    if (rows >= size_) return;
    while (!panels_.empty() && panels_.back()->row0 >= rows) panels_.pop_back();
    if (!panels_.empty()) {
        const Panel& p = *panels_.back();
        const int keep = rows - p.row0;
        if (keep < p.L.rows())
            panels_.back() = std::make_shared<Panel>(Panel{p.row0, p.L.topLeftCorner(keep, p.row0 + keep)});
    }
    size_ = rows;
    minDiagonal_ = std::numeric_limits<double>::infinity();
    maxDiagonal_ = 0.0;
    for (const auto& p : panels_)
        for (int i = 0; i < p->L.rows(); ++i) {
            minDiagonal_ = std::min(minDiagonal_, p->L(i, p->row0 + i));
            maxDiagonal_ = std::max(maxDiagonal_, p->L(i, p->row0 + i));
        }
}

void BorderedCholesky::remove(const std::vector<int>& indices) {
    if (indices.empty()) return;
    const int r0 = indices.front(), m = size_ - r0;
    // Rows r0 .. size() of L, whole: W = [L21 | T], T lower triangular (m x m).
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(m, size_);
    for (const auto& panel : panels_) {
        const Panel& p = *panel;
        const int h = static_cast<int>(p.L.rows());
        const int lo = std::max(r0, p.row0), hi = p.row0 + h;
        if (lo < hi) W.block(lo - r0, 0, hi - lo, p.L.cols()) = p.L.middleRows(lo - p.row0, hi - lo);
    }
    truncate(r0);  // the old rows r0 .. size() are in W now: freed before the new ones are made
    auto T = W.rightCols(m);
    std::vector<char> alive(m, 1);
    for (int j : indices) alive[j - r0] = 0;
    // Descending: every deleted index after j is gone (its column no longer read) when j goes.
    Eigen::VectorXd x(m);
    for (auto it = indices.rbegin(); it != indices.rend(); ++it) {
        const int j = *it - r0;
        x.tail(m - j - 1) = T.col(j).tail(m - j - 1);
        for (int k = j + 1; k < m; ++k) {
            if (!alive[k] || x[k] == 0.0) continue;
            const double lkk = T(k, k), r = std::hypot(lkk, x[k]);
            const double c = r / lkk, s = x[k] / lkk;
            T(k, k) = r;
            const int below = m - k - 1;
            auto lk = T.col(k).tail(below);
            auto xk = x.tail(below);
            lk = (lk + s * xk) / c;
            xk = c * xk - s * lk;
        }
    }
    // The kept rows and columns, compacted into panels of at most kRemovedPanelRows rows from row
    // r0 (lower triangle only, as extensions store it).
    std::vector<int> keep;
    for (int i = 0; i < m; ++i)
        if (alive[i]) keep.push_back(i);
    const int kept = static_cast<int>(keep.size());
    for (int a0 = 0; a0 < kept; a0 += kRemovedPanelRows) {
        const int h = std::min(kRemovedPanelRows, kept - a0);
        auto panel = std::make_shared<Panel>(Panel{r0 + a0, Eigen::MatrixXd::Zero(h, r0 + a0 + h)});
        for (int a = 0; a < h; ++a) {
            const int row = keep[a0 + a];
            panel->L.row(a).head(r0) = W.row(row).head(r0);
            for (int b = 0; b <= a0 + a; ++b) panel->L(a, r0 + b) = T(row, keep[b]);
            minDiagonal_ = std::min(minDiagonal_, panel->L(a, r0 + a0 + a));
            maxDiagonal_ = std::max(maxDiagonal_, panel->L(a, r0 + a0 + a));
        }
        panels_.push_back(std::move(panel));
    }
    size_ = r0 + kept;
}

double BorderedCholesky::diagonalRatio() const {
    return size_ == 0 ? 1.0 : (minDiagonal_ / maxDiagonal_) * (minDiagonal_ / maxDiagonal_);
}

Eigen::MatrixXd BorderedCholesky::product() const {
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(size_, size_);
    for (const auto& p : panels_) L.block(p->row0, 0, p->L.rows(), p->L.cols()) = p->L;
    return transposedProduct(L.transpose(), L.transpose());
}

std::size_t BorderedCholesky::bytes() const {
    std::size_t out = 0;
    for (const auto& p : panels_) out += sizeof(double) * p->L.size();
    return out;
}

}  // namespace btfracture
