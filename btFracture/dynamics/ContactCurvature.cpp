// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/ContactCurvature.h>

#include <btFracture/core/PortableMath.h>
#include <btFracture/dynamics/ClosestSurfacePoint.h>

#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace btfracture {

std::vector<double> vertexMeanCurvature(const TriangleMesh& mesh) {
    const std::size_t nv = mesh.vertices.size();
    std::vector<double> integrated(nv, 0.0), area(nv, 0.0);
    std::vector<Eigen::Vector3d> normals(mesh.triangles.size());
    // Directed edge (a, b) -> triangle index; the twin (b, a) belongs to the neighbour.
    std::map<std::pair<int, int>, int> edgeOwner;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d n = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                                      .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
        const double a = 0.5 * n.norm();
        normals[t] = a > 0.0 ? Eigen::Vector3d(n / (2.0 * a)) : Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
            area[tri[k]] += a / 3.0;
            edgeOwner[{tri[k], tri[(k + 1) % 3]}] = static_cast<int>(t);
        }
    }
    for (const auto& [edge, t] : edgeOwner) {
        if (edge.first > edge.second) continue;  // each undirected edge once
        const auto twin = edgeOwner.find({edge.second, edge.first});
        if (twin == edgeOwner.end()) continue;  // boundary edge
        const Eigen::Vector3d& n1 = normals[t];
        const Eigen::Vector3d& n2 = normals[twin->second];
        const Eigen::Vector3d e = mesh.vertices[edge.second] - mesh.vertices[edge.first];
        // Signed dihedral: positive when the surface turns away from its normal (convex edge).
        const double theta = pmath::atan2(n1.cross(n2).dot(e.normalized()), n1.dot(n2));
        const double contribution = theta * e.norm() / 4.0;
        integrated[edge.first] += contribution;
        integrated[edge.second] += contribution;
    }
    std::vector<double> curvature(nv, 0.0);
    for (std::size_t v = 0; v < nv; ++v)
        if (area[v] > 0.0) curvature[v] = integrated[v] / area[v];
    return curvature;
}

double meanCurvatureAt(const TriangleMesh& mesh, const std::vector<double>& vertexCurvature,
                       const Eigen::Vector3d& point) {
    const ClosestSurfacePoint closest = closestSurfacePoint(mesh, point);
    if (closest.triangle < 0 || vertexCurvature.size() != mesh.vertices.size()) return 0.0;
    const auto& t = mesh.triangles[closest.triangle];
    return closest.barycentric.x() * vertexCurvature[t[0]] + closest.barycentric.y() * vertexCurvature[t[1]] +
           closest.barycentric.z() * vertexCurvature[t[2]];
}

double shapeMeanCurvature(const btCollisionShape& shape, const Eigen::Vector3d& p) {
    switch (shape.getShapeType()) {
        case SPHERE_SHAPE_PROXYTYPE: {
            const double r = static_cast<const btSphereShape&>(shape).getRadius();
            return r > 0.0 ? 1.0 / r : 0.0;
        }
        case CAPSULE_SHAPE_PROXYTYPE: {
            const auto& capsule = static_cast<const btCapsuleShape&>(shape);
            const double r = capsule.getRadius();
            const double axial = std::abs(p[capsule.getUpAxis()]);
            if (!(r > 0.0)) return 0.0;
            return axial > capsule.getHalfHeight() ? 1.0 / r : 0.5 / r;
        }
        case CYLINDER_SHAPE_PROXYTYPE: {
            const auto& cylinder = static_cast<const btCylinderShape&>(shape);
            const int up = cylinder.getUpAxis();
            const double r = cylinder.getRadius();
            const double halfHeight = cylinder.getHalfExtentsWithMargin()[up];
            // On an end cap when the point sits closer to the cap plane than to the side.
            double radial2 = 0.0;
            for (int k = 0; k < 3; ++k)
                if (k != up) radial2 += p[k] * p[k];
            const bool onCap = halfHeight - std::abs(p[up]) < r - std::sqrt(radial2);
            return (!onCap && r > 0.0) ? 0.5 / r : 0.0;
        }
        default:
            return 0.0;
    }
}

}  // namespace btfracture
