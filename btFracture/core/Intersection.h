// SPDX-License-Identifier: Zlib
#pragma once
// Point-in-solid and segment-triangle queries on plain triangle data.
#include <Eigen/Core>

#include <array>
#include <vector>

namespace btfracture {

// Generalised winding number of a closed, outward-oriented triangle surface at p (van Oosterom
// & Strackee solid angles): about 1 inside, 0 outside.
double windingNumber(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<std::array<int, 3>>& triangles, const Eigen::Vector3d& p);

// Parameter t in [0, 1] where the segment p + t (q - p) crosses triangle (a, b, c), or a
// negative value if it misses (Moller & Trumbore).
double segmentTriangleHit(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace btfracture
