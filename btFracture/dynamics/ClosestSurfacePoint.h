// SPDX-License-Identifier: Zlib
#pragma once
// Closest point on a triangle mesh's surface (brute force over the triangles: meant for BEM and
// collision meshes of up to a few thousand triangles and a handful of queries per event).
#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct ClosestSurfacePoint {
    int triangle = -1;  // lowest index among equally close triangles; -1 for an empty mesh
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // of `point` in `triangle`
    double distance = 0.0;
};

// Expects valid indices (see inspectMesh).
ClosestSurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& p);

}  // namespace btfracture
