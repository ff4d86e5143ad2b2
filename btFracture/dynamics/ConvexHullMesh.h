#pragma once
// Closed triangle meshes for convex point sets and boxes, and a convexity test.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace btfracture {

// Outward-oriented closed mesh of the convex hull of `points` (Bullet's btConvexHullComputer;
// its coplanar faces are fan-triangulated); the corners are the input points, exactly. Throws
// btfracture::Error naming `name` when the points are not finite or span no volume (fewer than
// four affinely independent points).
TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name);

// The 8-vertex, 12-triangle mesh of the box [-h, h], outward-oriented.
TriangleMesh boxMesh(const Eigen::Vector3d& halfExtents, const std::string& name);

// True when every vertex lies on the inner side of every triangle's plane, within
// relativeTolerance times the bounding-box diagonal. Expects a closed, outward-oriented mesh.
bool isConvex(const TriangleMesh& mesh, double relativeTolerance = 1e-9);

}  // namespace btfracture
