#pragma once
// Closest point on a triangle mesh's surface (brute force over the triangles: meant for BEM and
// collision meshes of up to a few thousand triangles and a handful of queries per event).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct ClosestSurfacePoint {
    int triangle = -1;  // lowest index among equally close triangles; -1 for an empty mesh
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // of `point` in `triangle`
    double distance = 0.0;
};

// Closest point on triangle (a, b, c) to p (Voronoi regions of corners, edges, face).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Expects valid indices (see inspectMesh).
ClosestSurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& p);

}  // namespace btfracture
