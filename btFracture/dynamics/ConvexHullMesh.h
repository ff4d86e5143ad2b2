#pragma once
// Box meshes; convex hulls and the convexity test live in geometry/ConvexHull.h (included).
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace btfracture {

// The 8-vertex, 12-triangle mesh of the box [-h, h], outward-oriented.
TriangleMesh boxMesh(const Eigen::Vector3d& halfExtents, const std::string& name);

}  // namespace btfracture
