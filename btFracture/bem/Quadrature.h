// SPDX-License-Identifier: Zlib
#pragma once
// Quadrature rules on [0, 1] and on triangles (barycentric points, weights summing to 1).
#include <vector>

namespace btfracture {

struct LineRule {
    std::vector<double> points, weights;  // Gauss-Legendre on [0, 1]
};

struct TriangleRule {
    // Barycentric coordinates (l0, l1, l2) of each point and its weight; sum of weights = 1, so
    // that the integral over a triangle of area A is A * sum(w f).
    struct Point {
        double l0, l1, l2, w;
    };
    std::vector<Point> points;
    int degree = 0;  // polynomials up to this degree are integrated exactly
};

// n-point Gauss-Legendre rule on [0, 1], 1 <= n <= 40 (cached; thread-safe).
const LineRule& gaussLegendre(int n);

// Smallest cached rule exact for the given polynomial degree (1..30): symmetric rules up to
// degree 8 (Dunavant 1985; 1, 3, 6, 6, 7, 12, 16, 16 points), collapsed Gauss
// (Stroud conical product) beyond.
const TriangleRule& triangleRule(int degree);

}  // namespace btfracture
