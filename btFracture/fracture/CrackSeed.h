// SPDX-License-Identifier: Zlib
#pragma once
// Planar disc-shaped crack sheets: the initiation seed (a hexagon, one ring) and, with more
// rings, penny-shaped test cracks.
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

}  // namespace btfracture
