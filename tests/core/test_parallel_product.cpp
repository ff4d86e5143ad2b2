// SPDX-License-Identifier: Zlib
// transposedProduct (a^T b in fixed blocks on all cores): Eigen's product to rounding, and the
// same bits on any thread count. transposedTimes (a^T x) and productInDouble (a q, a in single
// precision): Eigen's single product bit for bit, on any thread count.
// Eigen's cache sizes are the pinned ones, not the CPU's.
#include <btFracture/core/Error.h>
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

TEST(ParallelProduct, MatrixVectorProductsAreEigensBitForBitOnAnyThreadCount) {
    // The BEM's K^T f and F q (3n x 3n and 3n x 3m), CrackSystem's C^T b and G^T q, remainders of
    // the 64-row and 8-row blocks, a single row or column and empty operands.
    struct Shape {
        int rows, cols;
    };
    for (const Shape s : {Shape{4500, 4500}, Shape{2253, 4506}, Shape{1003, 301}, Shape{300, 7},
                          Shape{7, 300}, Shape{1, 90}, Shape{90, 1}, Shape{0, 5}, Shape{5, 0}}) {
        const Eigen::MatrixXd a = Eigen::MatrixXd::Random(s.rows, s.cols);
        const Eigen::VectorXd x = Eigen::VectorXd::Random(s.rows), q = Eigen::VectorXd::Random(s.cols);
        const Eigen::Matrix<float, -1, -1, Eigen::RowMajor> f = a.cast<float>();
        const Eigen::VectorXd plainTransposed = a.transpose() * x;
        Eigen::VectorXd plainSingle(s.rows);
        for (int r = 0; r < s.rows; ++r) plainSingle(r) = (f.row(r).cast<double>() * q)(0);
        for (const int threads : {1, 2}) {
            const ThreadLimit limit(threads);
            const Eigen::VectorXd transposed = transposedTimes(a, x), single = productInDouble(f, q);
            ASSERT_EQ(transposed.size(), s.cols);
            ASSERT_EQ(single.size(), s.rows);
            EXPECT_TRUE(transposed == plainTransposed)
                << s.rows << " x " << s.cols << ", " << threads << " threads";
            EXPECT_TRUE(single == plainSingle) << s.rows << " x " << s.cols << ", " << threads << " threads";
        }
    }
    EXPECT_THROW(transposedTimes(Eigen::MatrixXd::Zero(3, 2), Eigen::VectorXd::Zero(2)), Error);
}

TEST(ParallelProduct, EigenBlockingIsFixedNotTheCpus) {
    // Eigen splits a product's depth in blocks sized by the L1 cache; the library pins the sizes
    // (btFracture/CMakeLists.txt) instead of asking CPUID, so that a portable binary rounds the same
    // on every CPU.
    EXPECT_EQ(Eigen::l1CacheSize(), EIGEN_DEFAULT_L1_CACHE_SIZE);
    EXPECT_EQ(Eigen::l2CacheSize(), EIGEN_DEFAULT_L2_CACHE_SIZE);
    EXPECT_EQ(Eigen::l3CacheSize(), EIGEN_DEFAULT_L3_CACHE_SIZE);
    // Why it matters: the same product with the depth blocks of a 32 KB L1 is not the same bits.
    const Eigen::MatrixXd a = Eigen::MatrixXd::Random(64, 1400), b = Eigen::MatrixXd::Random(1400, 64);
    const Eigen::MatrixXd pinned = a * b;
    Eigen::setCpuCacheSizes(32 * 1024, EIGEN_DEFAULT_L2_CACHE_SIZE, EIGEN_DEFAULT_L3_CACHE_SIZE);
    const Eigen::MatrixXd otherL1 = a * b;
    Eigen::setCpuCacheSizes(EIGEN_DEFAULT_L1_CACHE_SIZE, EIGEN_DEFAULT_L2_CACHE_SIZE,
                            EIGEN_DEFAULT_L3_CACHE_SIZE);
    EXPECT_FALSE(pinned == otherL1);
    EXPECT_LT((pinned - otherL1).norm(), 1e-12 * pinned.norm());
}
