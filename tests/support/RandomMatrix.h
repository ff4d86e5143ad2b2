// SPDX-License-Identifier: Zlib
#pragma once
// A seeded n x n matrix of entries uniform in [-1, 1), filled row by row: the same matrix on every
// machine for a given seed.
#include <Eigen/Core>

#include <random>

namespace btfracture::test {

inline Eigen::MatrixXd seededUniformMatrix(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd a(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) a(i, j) = u(rng);
    return a;
}

}  // namespace btfracture::test
