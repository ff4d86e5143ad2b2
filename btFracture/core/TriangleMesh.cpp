// SPDX-License-Identifier: Zlib
#include <btFracture/core/TriangleMesh.h>

namespace btfracture {

void removeUnusedVertices(TriangleMesh& mesh) {
    std::vector<int> remap(mesh.vertices.size(), -1);
    std::vector<Eigen::Vector3d> used;
    for (auto& tri : mesh.triangles)
        for (int& v : tri) {
            if (remap[v] < 0) {
                remap[v] = static_cast<int>(used.size());
                used.push_back(mesh.vertices[v]);
            }
            v = remap[v];
        }
    mesh.vertices = std::move(used);
}

}  // namespace btfracture
