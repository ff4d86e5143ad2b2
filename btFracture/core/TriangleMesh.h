// SPDX-License-Identifier: Zlib
#pragma once
// Plain indexed triangle mesh (counter-clockwise seen from outside = outward normals).
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace btfracture {

struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::string name;  // where it came from (file name or generator), used in messages
};

// Drops the vertices no triangle uses and numbers the rest in order of first use.
void removeUnusedVertices(TriangleMesh& mesh);

}  // namespace btfracture
