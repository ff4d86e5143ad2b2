// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/SurfaceDistance.h>

#include <btFracture/core/Error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace btfracture {

double maxDistanceToSurface(const TriangleMesh& from, const ClosestPointTree& to, double sampleSpacing) {
    const std::string source = from.name.empty() ? std::string("<unnamed mesh>") : from.name;
    if (from.triangles.empty()) throw Error(source + ": no triangles to sample for a surface distance");
    if (!(sampleSpacing > 0.0) || !std::isfinite(sampleSpacing))
        throw Error(source + ": surface distance sample spacing must be positive and finite, got " +
                    std::to_string(sampleSpacing));
    double worst2 = 0.0;
    auto sample = [&](const Eigen::Vector3d& p) {
        worst2 = std::max(worst2, to.closestPoint(p).squaredDistance);
    };
    for (const auto& v : from.vertices) sample(v);
    for (const auto& tri : from.triangles) {
        const Eigen::Vector3d& a = from.vertices[tri[0]];
        const Eigen::Vector3d& b = from.vertices[tri[1]];
        const Eigen::Vector3d& c = from.vertices[tri[2]];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int n = std::max(1, static_cast<int>(std::ceil(longest / sampleSpacing)));
        // Grid points other than the corners (already sampled as vertices).
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const int k = n - i - j;
                if (i == n || j == n || k == n) continue;
                sample((a * i + b * j + c * k) / n);
            }
    }
    return std::sqrt(worst2);
}

double hausdorffDistance(const TriangleMesh& a, const TriangleMesh& b, double relativeSpacing) {
    Eigen::AlignedBox3d box;
    for (const auto& v : a.vertices) box.extend(v);
    for (const auto& v : b.vertices) box.extend(v);
    const double spacing = relativeSpacing * box.diagonal().norm();
    return std::max(maxDistanceToSurface(a, ClosestPointTree(b), spacing),
                    maxDistanceToSurface(b, ClosestPointTree(a), spacing));
}

}  // namespace btfracture
