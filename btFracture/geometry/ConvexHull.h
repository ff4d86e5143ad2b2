// SPDX-License-Identifier: Zlib
#pragma once
// Convex hulls: the collision shape of the smallest fragments (paper §5.2 class (a)) and the
// operands of the overlap queries between fragments (ConvexPenetration.h).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace btfracture {

// Outward-oriented closed triangle mesh of the convex hull of `points` (quickhull on exact
// orientation tests, so any input gives a closed, convex mesh that contains every point); its
// corners are the extreme points among `points`, exactly (points inside the hull, on a face or
// on an edge are not corners). Deterministic: the same points in the same order give the same
// mesh. Throws btfracture::Error naming `name` when the points are not finite or span no volume
// (fewer than four affinely independent points).
TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name);

// True when every vertex lies on the inner side of every triangle's plane, within
// relativeTolerance times the bounding-box diagonal. Expects a closed, outward-oriented mesh.
bool isConvex(const TriangleMesh& mesh, double relativeTolerance = 1e-9);

}  // namespace btfracture
