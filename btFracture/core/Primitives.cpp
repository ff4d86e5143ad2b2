// SPDX-License-Identifier: Zlib
#include <btFracture/core/Primitives.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace btfracture {

TriangleMesh makeBox(const Eigen::Vector3d& h, double cellsPerUnit, const std::string& name) {
    auto cells = [cellsPerUnit](double halfExtent) {
        return std::max(1, static_cast<int>(std::lround(cellsPerUnit * 2.0 * halfExtent)));
    };
    TriangleMesh box = makeBox(h, cells(h.x()), cells(h.y()), cells(h.z()));
    box.name = name;
    return box;
}

TriangleMesh makeBox(const Eigen::Vector3d& h, int nx, int ny, int nz) {
    if (!(h.minCoeff() > 0.0) || nx < 1 || ny < 1 || nz < 1)
        throw Error("makeBox: half extents must be positive and cell counts at least 1");
    std::array<std::vector<double>, 3> lines;
    const int n[3] = {nx, ny, nz};
    for (int a = 0; a < 3; ++a)
        for (int g = 0; g <= n[a]; ++g) lines[a].push_back(h[a] * (2.0 * g / n[a] - 1.0));
    return makeGridBox(lines);
}

TriangleMesh makeGridBox(const std::array<std::vector<double>, 3>& lines) {
    for (const auto& l : lines)
        if (l.size() < 2 || std::adjacent_find(l.begin(), l.end(), std::greater_equal<double>()) != l.end())
            throw Error("makeGridBox: each axis needs at least two strictly increasing grid lines");
    TriangleMesh mesh;
    mesh.name = "box";
    std::map<std::array<int, 3>, int> index;  // integer lattice point -> vertex
    const int n[3] = {static_cast<int>(lines[0].size()) - 1, static_cast<int>(lines[1].size()) - 1,
                      static_cast<int>(lines[2].size()) - 1};
    auto vertex = [&](std::array<int, 3> g) {
        auto [it, inserted] = index.emplace(g, static_cast<int>(mesh.vertices.size()));
        if (inserted) mesh.vertices.push_back({lines[0][g[0]], lines[1][g[1]], lines[2][g[2]]});
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

TriangleMesh makeGeodesicSphere(double radius, int f) {
    if (!(radius > 0.0) || f < 1 || f > 256)
        throw Error("makeGeodesicSphere: radius must be positive and frequency in 1..256, got radius " +
                    std::to_string(radius) + ", frequency " + std::to_string(f));
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    const Eigen::Vector3d ico[12] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                     {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                     {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    TriangleMesh mesh;
    mesh.name = "geodesic-sphere";
    // A lattice point is identified by its integer weights on the icosahedron's vertices, so
    // points on shared edges and corners are created once.
    std::map<std::array<int, 12>, int> index;
    for (const auto& face : faces) {
        auto vertex = [&](int i, int j) {  // weights (f - i - j, i, j) on the face's corners
            std::array<int, 12> key{};
            key[face[0]] += f - i - j;
            key[face[1]] += i;
            key[face[2]] += j;
            auto [it, inserted] = index.emplace(key, static_cast<int>(mesh.vertices.size()));
            if (inserted) {
                const Eigen::Vector3d p = (f - i - j) * ico[face[0]] + i * ico[face[1]] + j * ico[face[2]];
                mesh.vertices.push_back(radius * p.normalized());
            }
            return it->second;
        };
        for (int i = 0; i < f; ++i)
            for (int j = 0; i + j < f; ++j) {
                mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)});
                if (i + j + 1 < f)
                    mesh.triangles.push_back({vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
            }
    }
    return mesh;
}

TriangleMesh makeTorus(double R, double r, int major, int minor) {
    if (!(r > 0.0 && r < R) || major < 3 || minor < 3)
        throw Error("makeTorus: needs 0 < r < R and at least 3 x 3 segments, got R " + std::to_string(R) +
                    ", r " + std::to_string(r) + ", " + std::to_string(major) + " x " +
                    std::to_string(minor));
    TriangleMesh m;
    m.name = "torus";
    for (int i = 0; i < major; ++i) {
        const double u = 2.0 * M_PI * i / major;
        for (int j = 0; j < minor; ++j) {
            const double v = 2.0 * M_PI * j / minor;
            m.vertices.emplace_back((R + r * pmath::cos(v)) * pmath::cos(u),
                                    (R + r * pmath::cos(v)) * pmath::sin(u), r * pmath::sin(v));
        }
    }
    auto id = [&](int i, int j) { return (i % major) * minor + (j % minor); };
    for (int i = 0; i < major; ++i)
        for (int j = 0; j < minor; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

}  // namespace btfracture
