// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/MeshQuality.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace btfracture {
namespace {

double cornerAngle(const Eigen::Vector3d& corner, const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    const Eigen::Vector3d e1 = u - corner, e2 = v - corner;
    return pmath::atan2(e1.cross(e2).norm(), e1.dot(e2));
}

}  // namespace

Eigen::Vector3d triangleAngles(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return {cornerAngle(a, b, c), cornerAngle(b, c, a), cornerAngle(c, a, b)};
}

double triangleMinAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    // The smallest angle lies opposite the shortest edge.
    const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
    if (bc <= ab && bc <= ca) return cornerAngle(a, b, c);
    if (ca <= ab) return cornerAngle(b, c, a);
    return cornerAngle(c, a, b);
}

MeshQuality measureQuality(const TriangleMesh& mesh, double angleThresholdDegrees) {
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (mesh.triangles.empty()) throw Error(source + ": measureQuality needs at least one triangle");
    const int nv = static_cast<int>(mesh.vertices.size());
    const double toDegrees = 180.0 / M_PI;

    MeshQuality q;
    q.triangleCount = static_cast<int>(mesh.triangles.size());
    q.angleThresholdDegrees = angleThresholdDegrees;
    q.minAngleDegrees = std::numeric_limits<double>::infinity();
    q.minEdgeLength = std::numeric_limits<double>::infinity();
    double minAngleSum = 0.0;
    std::vector<std::pair<int, int>> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (int t = 0; t < q.triangleCount; ++t) {
        const auto& tri = mesh.triangles[t];
        for (int i : tri)
            if (i < 0 || i >= nv)
                throw Error(source + ": triangle " + std::to_string(t) + " has vertex index " +
                            std::to_string(i) + " outside [0, " + std::to_string(nv) + ")");
        const Eigen::Vector3d angles =
            triangleAngles(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]) * toDegrees;
        const double smallest = angles.minCoeff();
        minAngleSum += smallest;
        if (smallest < q.minAngleDegrees) {
            q.minAngleDegrees = smallest;
            q.worstTriangle = t;
        }
        q.maxAngleDegrees = std::max(q.maxAngleDegrees, angles.maxCoeff());
        if (smallest < angleThresholdDegrees) ++q.trianglesBelowAngle;
        for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(tri[k], tri[(k + 1) % 3]));
    }
    q.meanMinAngleDegrees = minAngleSum / q.triangleCount;

    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    double lengthSum = 0.0;
    for (const auto& [a, b] : edges) {
        const double length = (mesh.vertices[a] - mesh.vertices[b]).norm();
        q.minEdgeLength = std::min(q.minEdgeLength, length);
        q.maxEdgeLength = std::max(q.maxEdgeLength, length);
        lengthSum += length;
    }
    q.meanEdgeLength = lengthSum / static_cast<double>(edges.size());
    q.edgeLengthRatio =
        q.minEdgeLength > 0.0 ? q.maxEdgeLength / q.minEdgeLength : std::numeric_limits<double>::infinity();
    return q;
}

}  // namespace btfracture
