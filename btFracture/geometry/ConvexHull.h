// SPDX-License-Identifier: Zlib
#pragma once
// Convex hulls: the collision shape of the smallest fragments (paper §5.2 class (a)) and the
// operands of the overlap queries between fragments (ConvexPenetration.h).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace btfracture {

// Outward-oriented closed triangle mesh of the convex hull of `points`: quickhull on exact integer
// orientation tests of the points snapped to a grid of power-of-two cells, 2^40 cells across the
// largest side of their bounding box (cell <= 2^-40 of that side). The mesh's corners are input
// points, exactly: those whose grid points are extreme on the grid's hull (grid points inside it,
// on a face or on an edge are not corners). So the mesh is closed and convex, and contains every
// point, up to the snapping (each point moves by at most half a cell per axis). Deterministic, on
// every CPU: the same points in the same order give the same mesh. Throws btfracture::Error naming
// `name` when a point is not finite or beyond 1e300, or the grid points span no volume (fewer
// than four affinely independent ones).
TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name);

// Volume of convexHullMesh(points) [m^3]; 0 when the points span no volume. Throws
// btfracture::Error naming `name` when a point is not finite or beyond 1e300.
double convexHullVolume(const std::vector<Eigen::Vector3d>& points, const std::string& name);

// True when every vertex lies on the inner side of every triangle's plane, within
// relativeTolerance times the bounding-box diagonal. Expects a closed, outward-oriented mesh.
bool isConvex(const TriangleMesh& mesh, double relativeTolerance = 1e-9);

}  // namespace btfracture
