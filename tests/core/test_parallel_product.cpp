// SPDX-License-Identifier: Zlib
// transposedProduct (a^T b in fixed blocks on all cores): Eigen's product to rounding, and the
// same bits on any thread count.
#include <btFracture/core/ParallelProduct.h>
#include <btFracture/core/ThreadLimit.h>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cstdio>

using namespace btfracture;

TEST(ParallelProduct, TransposedProductIsEigensForAnyShapeAndThreadCount) {
    // Shapes of CrackSystem's Schur columns (few columns of b, thousands of rows of a^T b), of
    // BorderedCholesky's X^T X, remainders of the 256-row and 64-column blocks, a short depth and
    // empty operands.
    struct Shape {
        int k, m, n;
    };
    for (const Shape s : {Shape{2274, 3465, 6}, Shape{900, 700, 130}, Shape{300, 513, 65}, Shape{5, 767, 3},
                          Shape{40, 200, 1}, Shape{10, 0, 4}, Shape{10, 4, 0}}) {
        const Eigen::MatrixXd a = Eigen::MatrixXd::Random(s.k, s.m), b = Eigen::MatrixXd::Random(s.k, s.n);
        const Eigen::MatrixXd plain = a.transpose() * b;
        Eigen::MatrixXd one, two;
        {
            const ThreadLimit limit(1);
            one = transposedProduct(a, b);
        }
        {
            const ThreadLimit limit(2);
            two = transposedProduct(a, b);
        }
        ASSERT_EQ(one.rows(), s.m);
        ASSERT_EQ(one.cols(), s.n);
        if (plain.size() == 0) continue;
        const double difference = (one - plain).norm() / plain.norm();
        std::printf("k %d, m %d, n %d: relative difference to one product %.1e\n", s.k, s.m, s.n, difference);
        EXPECT_LT(difference, 1e-14);
        EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
    }
}
