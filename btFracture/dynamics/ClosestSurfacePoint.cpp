// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/ClosestSurfacePoint.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace btfracture {

namespace {

Eigen::Vector3d barycentricOf(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    if (!(n2 > 0.0)) return Eigen::Vector3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    const double u = (c - b).cross(q - b).dot(n) / n2;
    const double v = (a - c).cross(q - c).dot(n) / n2;
    return Eigen::Vector3d(u, v, 1.0 - u - v);
}

}  // namespace

ClosestSurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
    ClosestSurfacePoint best;
    double bestDistance2 = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const Eigen::Vector3d q =
            closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        const double d2 = (q - p).squaredNorm();
        if (d2 < bestDistance2) {
            bestDistance2 = d2;
            best.triangle = static_cast<int>(e);
            best.point = q;
        }
    }
    if (best.triangle < 0) return best;
    const auto& t = mesh.triangles[best.triangle];
    best.barycentric =
        barycentricOf(best.point, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    best.distance = std::sqrt(bestDistance2);
    return best;
}

}  // namespace btfracture
