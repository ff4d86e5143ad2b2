// SPDX-License-Identifier: Zlib
#include <btFracture/io/CrackFaces.h>

namespace btfracture {

std::vector<bool> crackFaces(const TriangleMesh& fragment, const Eigen::Isometry3d& originalFromFragment,
                             const ClosestPointTree& original, double tolerance) {
    constexpr double kMinCosine = 0.5;  // 60 degrees
    std::vector<bool> crack(fragment.triangles.size(), true);
    for (size_t t = 0; t < fragment.triangles.size(); ++t) {
        const auto& tri = fragment.triangles[t];
        const Eigen::Vector3d a = originalFromFragment * fragment.vertices[tri[0]];
        const Eigen::Vector3d b = originalFromFragment * fragment.vertices[tri[1]];
        const Eigen::Vector3d c = originalFromFragment * fragment.vertices[tri[2]];
        const Eigen::Vector3d normal = (b - a).cross(c - a);
        if (!(normal.norm() > 0.0)) continue;  // degenerate: counted with the cut
        const ClosestPointTree::Hit hit =
            original.closestPointWithin((a + b + c) / 3.0, normal.normalized(), kMinCosine, tolerance);
        crack[t] = hit.triangle < 0;
    }
    return crack;
}

}  // namespace btfracture
