// SPDX-License-Identifier: Zlib
// BorderedCholesky: a factor grown block by block solves like one factorisation of the whole
// matrix, rejects a border that breaks positive definiteness without changing, and gives the
// same bits on any thread count.
#include <btFracture/bem/BorderedCholesky.h>
#include <btFracture/core/ThreadLimit.h>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

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
        // Columns of S from the factor, across and inside the extensions' panels.
        for (const auto& [first, count] : {std::pair{0, 150}, {20, 45}, {149, 1}})
            EXPECT_LT((f.productColumns(first, count) - s.middleCols(first, count)).cwiseAbs().maxCoeff(),
                      1e-12 * s.cwiseAbs().maxCoeff());
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
// grows again from there like one grown to that size (the crack system refactors from the first
// slot whose unknown's basis function changed).
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
