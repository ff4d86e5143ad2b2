// SPDX-License-Identifier: Zlib
#pragma once
// Plain indexed triangle mesh (counter-clockwise seen from outside = outward normals).
#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace btfracture {

struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::string name;  // where it came from (file name or generator), used in messages
};

// Fills mesh.vertices with the vertices mesh.triangles use, numbered in order of first use. On
// entry the triangles index a source of `sourceVertices` vertices, vertex i at position(i);
// the others are never read.
template <class Position>
void takeUsedVertices(TriangleMesh& mesh, std::size_t sourceVertices, Position&& position) {
    std::vector<int> remap(sourceVertices, -1);
    mesh.vertices.clear();
    for (auto& tri : mesh.triangles)
        for (int& v : tri) {
            if (remap[v] < 0) {
                remap[v] = static_cast<int>(mesh.vertices.size());
                mesh.vertices.push_back(position(v));
            }
            v = remap[v];
        }
}

}  // namespace btfracture
