#include <btFracture/core/Primitives.h>

#include <btFracture/core/Error.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace btfracture {

TriangleMesh makeBox(const Eigen::Vector3d& h, double cellsPerUnit) {
    auto cells = [cellsPerUnit](double halfExtent) {
        return std::max(1, static_cast<int>(std::lround(cellsPerUnit * 2.0 * halfExtent)));
    };
    return makeBox(h, cells(h.x()), cells(h.y()), cells(h.z()));
}

TriangleMesh makeBox(const Eigen::Vector3d& h, int nx, int ny, int nz) {
    if (!(h.minCoeff() > 0.0) || nx < 1 || ny < 1 || nz < 1)
        throw Error("makeBox: half extents must be positive and cell counts at least 1");
    TriangleMesh mesh;
    mesh.name = "box";
    std::map<std::array<int, 3>, int> index;  // integer lattice point -> vertex
    const int n[3] = {nx, ny, nz};
    auto vertex = [&](std::array<int, 3> g) {
        auto [it, inserted] = index.emplace(g, static_cast<int>(mesh.vertices.size()));
        if (inserted)
            mesh.vertices.push_back({h.x() * (2.0 * g[0] / nx - 1.0), h.y() * (2.0 * g[1] / ny - 1.0),
                                     h.z() * (2.0 * g[2] / nz - 1.0)});
        return it->second;
    };
    // Face normal along axis a, side s (0: -, 1: +); (b, c) span the face so that b x c = +axis.
    for (int a = 0; a < 3; ++a)
        for (int s = 0; s < 2; ++s) {
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            for (int i = 0; i < n[b]; ++i)
                for (int j = 0; j < n[c]; ++j) {
                    std::array<int, 3> g00{}, g10{}, g11{}, g01{};
                    for (auto* g : {&g00, &g10, &g11, &g01}) (*g)[a] = s * n[a];
                    g00[b] = i, g00[c] = j;
                    g10[b] = i + 1, g10[c] = j;
                    g11[b] = i + 1, g11[c] = j + 1;
                    g01[b] = i, g01[c] = j + 1;
                    const int v00 = vertex(g00), v10 = vertex(g10), v11 = vertex(g11), v01 = vertex(g01);
                    if (s == 1) {
                        mesh.triangles.push_back({v00, v10, v11});
                        mesh.triangles.push_back({v00, v11, v01});
                    } else {
                        mesh.triangles.push_back({v00, v11, v10});
                        mesh.triangles.push_back({v00, v01, v11});
                    }
                }
        }
    return mesh;
}

TriangleMesh makeIcosphere(double radius, int level) {
    if (!(radius > 0.0) || level < 0 || level > 7)
        throw Error("makeIcosphere: radius must be positive and level in 0..7, got radius " + std::to_string(radius) +
                    ", level " + std::to_string(level));
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    TriangleMesh mesh;
    mesh.name = "icosphere";
    mesh.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                     {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& v : mesh.vertices) v.normalize();
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> midpoint;
        auto middle = [&](int a, int b) {
            auto [it, inserted] = midpoint.emplace(std::make_pair(std::min(a, b), std::max(a, b)), 0);
            if (inserted) {
                it->second = static_cast<int>(mesh.vertices.size());
                mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
            }
            return it->second;
        };
        std::vector<std::array<int, 3>> finer;
        finer.reserve(4 * mesh.triangles.size());
        for (const auto& tri : mesh.triangles) {
            const int ab = middle(tri[0], tri[1]), bc = middle(tri[1], tri[2]), ca = middle(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    for (auto& v : mesh.vertices) v *= radius;
    return mesh;
}

}  // namespace btfracture
