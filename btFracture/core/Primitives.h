// SPDX-License-Identifier: Zlib
#pragma once
// Closed triangle meshes of simple solids, outward oriented, for tests, demos and Bullet
// primitives that need a surface mesh.
#include <btFracture/core/TriangleMesh.h>

#include <array>
#include <string>
#include <vector>

namespace btfracture {

// Box centred at the origin with the given half extents [m]; each face is split into a grid of
// about `cellsPerUnit * edge length` squares (at least one per direction, so the default is the
// 8-vertex, 12-triangle box), two triangles each. `name` goes into the mesh for messages.
TriangleMesh makeBox(const Eigen::Vector3d& halfExtents, double cellsPerUnit = 0.0,
                     const std::string& name = "box");

// Box with an explicit number of grid cells along x, y and z.
TriangleMesh makeBox(const Eigen::Vector3d& halfExtents, int cellsX, int cellsY, int cellsZ);

// Box whose faces are gridded along the given lines: lines[a] holds the increasing coordinates
// (at least two; the first and last are the box's faces) of the grid planes normal to axis a.
TriangleMesh makeGridBox(const std::array<std::vector<double>, 3>& lines);

// Geodesic sphere of the given radius [m]: each icosahedron face split into frequency^2
// triangles (20 f^2 in all), vertices projected onto the sphere. Frequency 2^k gives the
// k-times subdivided icosphere.
TriangleMesh makeGeodesicSphere(double radius, int frequency);

// Torus around the z axis: major radius R, tube radius r [m], `major` x `minor` quads split into
// two triangles each (2 major minor triangles). Throws btfracture::Error unless 0 < r < R and
// major, minor >= 3.
TriangleMesh makeTorus(double R, double r, int major, int minor);

}  // namespace btfracture
