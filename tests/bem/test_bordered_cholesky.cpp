// SPDX-License-Identifier: Zlib
// BorderedCholesky: a factor grown block by block solves like one factorisation of the whole
// matrix, rejects a border that breaks positive definiteness without changing, and gives the
// same bits on any thread count.
#include <btFracture/bem/BorderedCholesky.h>
#include <btFracture/core/ThreadLimit.h>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <vector>

#include "../support/RandomMatrix.h"

using namespace btfracture;

namespace {

// A seeded SPD matrix with condition number about 1e4.
Eigen::MatrixXd spdMatrix(int n) {
    const Eigen::MatrixXd a = test::seededUniformMatrix(n, 7);
    Eigen::MatrixXd s = a * a.transpose() / n;
    s.diagonal().array() += 1e-2;
    return s;
}

BorderedCholesky grown(const Eigen::MatrixXd& s, const std::vector<int>& sizes) {
    BorderedCholesky f;
    int done = 0;
    for (int h : sizes) {
        EXPECT_TRUE(f.extend(s.block(0, done, done + h, h)));
        done += h;
    }
    return f;
}

}  // namespace

TEST(BorderedCholesky, GrownInBlocksSolvesLikeOneFactorisation) {
    const Eigen::MatrixXd s = spdMatrix(150);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(150, -1.0, 2.0);
    const Eigen::VectorXd exact = s.llt().solve(b);
    for (const std::vector<int>& sizes : {std::vector<int>{150}, {1, 60, 89}, {33, 33, 33, 51}}) {
        const BorderedCholesky f = grown(s, sizes);
        ASSERT_EQ(f.size(), 150);
        Eigen::VectorXd x = b;
        f.solveInPlace(x);
        EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm());
        EXPECT_LT((s * x - b).norm(), 1e-12 * b.norm() * s.norm());
        // Rows of each extension only: N^2 / 2 + sum h^2 / 2 entries, not N^2.
        std::size_t entries = 0, row0 = 0;
        for (int h : sizes) entries += h * (row0 += h);
        EXPECT_EQ(f.bytes(), sizeof(double) * entries);
        EXPECT_LT((f.product() - s).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff());
    }
}

TEST(BorderedCholesky, RejectsABorderThatIsNotPositiveDefinite) {
    Eigen::MatrixXd s = spdMatrix(40);
    BorderedCholesky f = grown(s, {30});
    // Rows 30..39 made a copy of row 0 (and column): the grown matrix is singular.
    for (int i = 30; i < 40; ++i) {
        s.row(i) = s.row(0);
        s.col(i) = s.col(0);
    }
    EXPECT_FALSE(f.extend(s.block(0, 30, 40, 10)));
    EXPECT_EQ(f.size(), 30);
    // A diagonal ratio floor: a well-conditioned border passes a loose one, fails a strict one.
    const Eigen::MatrixXd good = spdMatrix(40);
    BorderedCholesky g = grown(good, {30});
    EXPECT_FALSE(g.extend(good.block(0, 30, 40, 10), 0.99));
    EXPECT_TRUE(g.extend(good.block(0, 30, 40, 10), 1e-12));
    EXPECT_GT(g.diagonalRatio(), 1e-12);
}

// Truncated inside a block or at a block's edge, the factor is that of the leading block, and it
// grows again from there like one grown to that size (on LU, the crack system keeps the Cholesky
// factor of S's leading slots only up to the first slot whose unknown's basis function changed).
TEST(BorderedCholesky, TruncatedFactorIsTheLeadingBlocksAndGrowsAgain) {
    const Eigen::MatrixXd s = spdMatrix(120);
    for (int rows : {0, 33, 50, 97}) {
        BorderedCholesky f = grown(s, {33, 64, 23});
        f.truncate(rows);
        ASSERT_EQ(f.size(), rows);
        if (rows > 0) {
            const Eigen::MatrixXd lead = s.topLeftCorner(rows, rows);
            EXPECT_LT((f.product() - lead).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff()) << rows;
        }
        EXPECT_TRUE(f.extend(s.block(0, rows, 120, 120 - rows))) << rows;
        Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(120, -1.0, 2.0);
        const Eigen::VectorXd b = x;
        f.solveInPlace(x);
        EXPECT_LT((s * x - b).norm(), 1e-12 * b.norm() * s.norm()) << rows;
        EXPECT_GT(f.diagonalRatio(), 0.0) << rows;
    }
}

// Deleting rows and columns anywhere (inside a panel, across panels, the first and the last)
// leaves the factor of the matrix without them, which then grows on like one factored anew; a
// copy made before is not changed.
TEST(BorderedCholesky, RemovedIndicesLeaveTheFactorOfTheRest) {
    struct Case {
        int n;
        std::vector<int> extensions, removed;
    };
    const std::vector<Case> cases = {{120, {33, 64, 23}, {0}},
                                     {120, {33, 64, 23}, {119}},
                                     {120, {33, 64, 23}, {40, 41, 42}},
                                     {120, {33, 64, 23}, {5, 34, 35, 36, 90, 118}},
                                     {120, {33, 64, 23}, {33, 96, 97}},
                                     {500, {150, 350}, {3, 4, 5, 260, 499}}};  // rebuilt in several panels
    for (const auto& [size, extensions, removed] : cases) {
        const Eigen::MatrixXd s = spdMatrix(size);
        BorderedCholesky f = grown(s, extensions);
        const BorderedCholesky original = f;  // shares f's panels
        f.remove(removed);
        std::vector<int> kept;
        for (int i = 0; i < size; ++i)
            if (std::find(removed.begin(), removed.end(), i) == removed.end()) kept.push_back(i);
        const int n = static_cast<int>(kept.size());
        ASSERT_EQ(f.size(), n);
        Eigen::MatrixXd rest(n, n);
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) rest(a, b) = s(kept[a], kept[b]);
        EXPECT_LT((f.product() - rest).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff()) << removed[0];
        // Grown again by the removed indices, now last.
        Eigen::MatrixXd border(size, static_cast<int>(removed.size()));
        std::vector<int> order = kept;
        order.insert(order.end(), removed.begin(), removed.end());
        for (int a = 0; a < size; ++a)
            for (int b = 0; b < border.cols(); ++b) border(a, b) = s(order[a], removed[b]);
        ASSERT_TRUE(f.extend(border));
        Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(size, -1.0, 2.0);
        const Eigen::VectorXd b = x;
        f.solveInPlace(x);
        Eigen::MatrixXd permuted(size, size);
        for (int a = 0; a < size; ++a)
            for (int c = 0; c < size; ++c) permuted(a, c) = s(order[a], order[c]);
        EXPECT_LT((permuted * x - b).norm(), 1e-12 * b.norm() * s.norm()) << removed[0];
        EXPECT_GT(f.diagonalRatio(), 0.0);
        // The copy is the factor of the whole matrix still.
        ASSERT_EQ(original.size(), size);
        EXPECT_LT((original.product() - s).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff());
    }
}

TEST(BorderedCholesky, SameBitsOnAnyThreadCount) {
    const Eigen::MatrixXd s = spdMatrix(300);
    auto solve = [&](int threads) {
        const ThreadLimit limit(threads);
        const BorderedCholesky f = grown(s, {100, 120, 80});
        Eigen::VectorXd x = Eigen::VectorXd::Ones(300);
        f.solveInPlace(x);
        return x;
    };
    EXPECT_EQ((solve(1) - solve(2)).cwiseAbs().maxCoeff(), 0.0);
}
