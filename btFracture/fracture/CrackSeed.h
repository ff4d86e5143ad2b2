// SPDX-License-Identifier: Zlib
#pragma once
// Planar disc-shaped crack sheets: the initiation seeds (a one-ring hexagon inside the body, or a
// two-ring half-hexagon on its surface) and, with more rings, penny-shaped and semicircular test
// cracks.
#include <btFracture/bem/CrackMesh.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

// Adds a disc of the given radius [m] around `centre` with crack normal `normal` to `cracks`:
// `rings` concentric rings with 6 k nodes on ring k, triangulated ring to ring (6 rings^2
// triangles). `rotation` turns the node pattern about the normal [rad]. Returns the new
// triangles.
std::vector<int> addDiscCrack(CrackMesh& cracks, const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                              double radius, int rings, double rotation = 0.0);

// Adds half such a disc: the half on the `inward` side (in the crack plane, unit) of the diameter
// through `centre` along normal x inward, with 3 k + 1 nodes on ring k from one end of the
// diameter to the other. On a flat face whose tangent plane contains that diameter, the nodes on
// it lie on the surface: a semicircular surface crack whose mouth is the diameter. Returns the new
// triangles.
std::vector<int> addHalfDiscCrack(CrackMesh& cracks, const Eigen::Vector3d& centre,
                                  const Eigen::Vector3d& normal, const Eigen::Vector3d& inward, double radius,
                                  int rings);

}  // namespace btfracture
