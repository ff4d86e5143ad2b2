// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/HullSimplification.h>

#include <algorithm>
#include <cmath>

namespace btfracture {

std::vector<Eigen::Vector3d> budgetHullPoints(const std::vector<Eigen::Vector3d>& points, int maxVertices) {
    if (maxVertices <= 0 || points.size() <= static_cast<std::size_t>(maxVertices)) return points;
    // Support points are taken about the centroid so that the directions sample the shape evenly.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    const int directions = 2 * maxVertices;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    std::vector<char> chosen(points.size(), 0);
    int count = 0;
    for (int d = 0; d < directions && count < maxVertices; ++d) {
        // Fibonacci lattice: z evenly spaced in (-1, 1), longitude advancing by the golden angle.
        const double z = 1.0 - (2.0 * d + 1.0) / directions;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d n(r * std::cos(golden * d), r * std::sin(golden * d), z);
        std::size_t best = 0;
        double bestDot = -INFINITY;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const double dot = n.dot(points[k] - centre);
            if (dot > bestDot) {
                bestDot = dot;
                best = k;
            }
        }
        if (!chosen[best]) {
            chosen[best] = 1;
            ++count;
        }
    }
    std::vector<Eigen::Vector3d> subset;
    subset.reserve(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < points.size(); ++k)
        if (chosen[k]) subset.push_back(points[k]);
    return subset;
}

}  // namespace btfracture
