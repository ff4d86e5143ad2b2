// SPDX-License-Identifier: Zlib
// BorderedLU: factors grown block by block solve a symmetric indefinite matrix like one LU of the
// whole, truncation keeps whole blocks and grows again to the same solution, and a singular new
// block is rejected without changing the factors.
#include <btFracture/bem/BorderedLU.h>

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>

#include "../support/RandomMatrix.h"

using namespace btfracture;

namespace {

// A seeded symmetric indefinite matrix: eigenvalues of both signs, none closer to 0 than 0.05.
Eigen::MatrixXd indefiniteMatrix(int n) {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(test::seededUniformMatrix(n, 11));
    const Eigen::MatrixXd q = qr.householderQ();
    Eigen::VectorXd eigenvalues(n);
    for (int i = 0; i < n; ++i) eigenvalues[i] = (i % 3 == 0 ? -1.0 : 1.0) * (0.05 + 2.0 * i / n);
    return q * eigenvalues.asDiagonal() * q.transpose();
}

double norm1(const Eigen::MatrixXd& s, int n) {
    return s.topLeftCorner(n, n).cwiseAbs().colwise().sum().maxCoeff();
}

// Grows factors of `s` from `from` rows in blocks of `sizes`.
void grow(BorderedLU& f, const Eigen::MatrixXd& s, const std::vector<int>& sizes) {
    int done = f.size();
    for (int h : sizes) {
        EXPECT_GT(
            f.extend(s.block(0, done, done + h, h), s.block(done, 0, h, done), norm1(s, done + h), 1e-15),
            1e-15);
        done += h;
    }
}

double relativeError(const Eigen::VectorXd& x, const Eigen::VectorXd& exact) {
    return (x - exact).norm() / exact.norm();
}

}  // namespace

TEST(BorderedLU, GrownInBlocksSolvesLikeOneFactorisation) {
    const Eigen::MatrixXd s = indefiniteMatrix(120);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(120, -1.0, 2.0);
    const Eigen::VectorXd exact = s.partialPivLu().solve(b);
    BorderedLU f;
    grow(f, s, {30, 45, 3, 42});
    EXPECT_EQ(f.size(), 120);
    EXPECT_EQ(f.blocks(), 4);
    Eigen::VectorXd x = b;
    f.solveInPlace(x);
    // Condition number 41 / 0.05 ~ 800: agreement to ~1e-13 with one LU, bound 1e-10.
    EXPECT_LT(relativeError(x, exact), 1e-10);
    EXPECT_LT((s * x - b).norm() / (s.norm() * x.norm()), 1e-14);
}

TEST(BorderedLU, TruncationKeepsWholeBlocksAndGrowsAgain) {
    const Eigen::MatrixXd s = indefiniteMatrix(90);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(90);
    const Eigen::VectorXd exact = s.partialPivLu().solve(b);
    BorderedLU f;
    grow(f, s, {30, 30, 30});
    EXPECT_EQ(f.truncate(90), 90);
    EXPECT_EQ(f.truncate(59), 30);  // the block of rows 30-59 ends after row 58
    EXPECT_EQ(f.size(), 30);
    EXPECT_EQ(f.blocks(), 1);
    grow(f, s, {60});
    Eigen::VectorXd x = b;
    f.solveInPlace(x);
    EXPECT_LT(relativeError(x, exact), 1e-10);
    EXPECT_EQ(f.truncate(10), 0);
    EXPECT_EQ(f.blocks(), 0);
}

TEST(BorderedLU, SingularBlockIsRejectedWithoutChange) {
    Eigen::MatrixXd s = indefiniteMatrix(60);
    // Rows and columns 40-59 mix 0-20 (rounded): the grown matrix is singular to working
    // precision, its first 40 rows are not. E - X Y is rounding noise, well conditioned in itself.
    s.bottomRows(20) = (0.3 * s.topRows(20) + 0.7 * s.middleRows(1, 20)).eval();
    s.rightCols(20) = (0.3 * s.leftCols(20) + 0.7 * s.middleCols(1, 20)).eval();
    BorderedLU f;
    grow(f, s, {40});
    const double rcond = f.extend(s.block(0, 40, 60, 20), s.block(40, 0, 20, 40), norm1(s, 60), 1e-15);
    EXPECT_LE(rcond, 1e-15);
    EXPECT_EQ(f.size(), 40);
    EXPECT_EQ(f.blocks(), 1);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(40);
    Eigen::VectorXd x = b;
    f.solveInPlace(x);
    EXPECT_LT(relativeError(x, s.topLeftCorner(40, 40).partialPivLu().solve(b)), 1e-10);
}
