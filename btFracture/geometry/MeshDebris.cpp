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
    std::vector<char> keptTriangles(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        keptTriangles[t] = keep[sets.find(mesh.triangles[t][0])];
    keepTriangles(mesh, keptTriangles);
    return dropped;
}

void keepTriangles(TriangleMesh& mesh, const std::vector<char>& keep) {
    std::vector<int> newIndex(mesh.vertices.size(), -1);
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!keep[t]) continue;
        std::array<int, 3> tri = mesh.triangles[t];
        for (int& v : tri) {
            if (newIndex[v] < 0) {
                newIndex[v] = static_cast<int>(vertices.size());
                vertices.push_back(mesh.vertices[v]);
            }
            v = newIndex[v];
        }
        triangles.push_back(tri);
    }
    mesh.vertices = std::move(vertices);
    mesh.triangles = std::move(triangles);
}

}  // namespace btfracture
