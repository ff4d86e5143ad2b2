// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/HullSimplification.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace btfracture {

std::vector<Eigen::Vector3d> budgetHullPoints(const std::vector<Eigen::Vector3d>& points, int maxVertices) {
    if (maxVertices <= 0 || points.size() <= static_cast<std::size_t>(maxVertices)) return points;
    // Support points are taken about the centroid so that the directions sample the shape evenly.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    std::vector<char> chosen(points.size(), 0);
    int count = 0;
    // The point farthest along direction d of a Fibonacci lattice of n directions: z evenly
    // spaced in (-1, 1), longitude advancing by the golden angle.
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    const auto take = [&](int d, int n) {
        const double z = 1.0 - (2.0 * d + 1.0) / n;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d direction(r * std::cos(golden * d), r * std::sin(golden * d), z);
        std::size_t best = 0;
        double bestDot = -INFINITY;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const double dot = direction.dot(points[k] - centre);
            if (dot > bestDot) {
                bestDot = dot;
                best = k;
            }
        }
        if (!chosen[best]) {
            chosen[best] = 1;
            ++count;
        }
    };
    // First maxVertices directions (all of them: at most maxVertices points), then a lattice four
    // times as dense visited in a scrambled order (a stride coprime to its size), so that the
    // points filling the budget are spread over the whole sphere, not the first band of z.
    for (int d = 0; d < maxVertices; ++d) take(d, maxVertices);
    const int dense = 4 * maxVertices;
    int stride = static_cast<int>(0.618 * dense);
    while (std::gcd(stride, dense) != 1) ++stride;
    for (int k = 0, d = 0; k < dense && count < maxVertices; ++k, d = (d + stride) % dense) take(d, dense);
    std::vector<Eigen::Vector3d> subset;
    subset.reserve(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < points.size(); ++k)
        if (chosen[k]) subset.push_back(points[k]);
    return subset;
}

}  // namespace btfracture
