// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/MeshDebris.h>

#include <btFracture/core/UnionFind.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace btfracture {

DroppedDebris dropDebris(TriangleMesh& mesh, double fraction) {
    DroppedDebris dropped;
    const int nv = static_cast<int>(mesh.vertices.size());
    UnionFind sets(nv);
    for (const auto& t : mesh.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[1], t[2]);
    }
    // Enclosed volume per component (divergence theorem; a cavity's is negative).
    std::vector<double> volume(nv, 0.0);
    for (const auto& t : mesh.triangles)
        volume[sets.find(t[0])] +=
            mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
    std::vector<char> root(nv, 0);
    for (const auto& t : mesh.triangles) root[sets.find(t[0])] = 1;
    double largest = 0.0;
    int components = 0;
    for (int v = 0; v < nv; ++v)
        if (root[v]) {
            ++components;
            largest = std::max(largest, std::abs(volume[v]));
        }
    if (components < 2) return dropped;
    std::vector<char> keep(nv, 0);
    for (int v = 0; v < nv; ++v)
        if (root[v]) {
            keep[v] = std::abs(volume[v]) >= fraction * largest;
            if (!keep[v]) {
                ++dropped.pieces;
                dropped.volume += std::abs(volume[v]);
            }
        }
    if (dropped.pieces == 0) return dropped;
    std::vector<int> newIndex(nv, -1);
    TriangleMesh kept;
    kept.name = mesh.name;
    for (const auto& t : mesh.triangles) {
        if (!keep[sets.find(t[0])]) continue;
        std::array<int, 3> out{};
        for (int k = 0; k < 3; ++k) {
            if (newIndex[t[k]] < 0) {
                newIndex[t[k]] = static_cast<int>(kept.vertices.size());
                kept.vertices.push_back(mesh.vertices[t[k]]);
            }
            out[k] = newIndex[t[k]];
        }
        kept.triangles.push_back(out);
    }
    mesh = std::move(kept);
    return dropped;
}

}  // namespace btfracture
