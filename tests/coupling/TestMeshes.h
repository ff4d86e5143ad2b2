// SPDX-License-Identifier: Zlib
#pragma once
// Closed test meshes: prisms over simple polygons (the non-convex L shape).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace btfracture::test {

// Prism of a counter-clockwise polygon (x, y) from z = -h to +h. The caps are fanned from
// polygon vertex `fanFrom`, which must see the whole polygon (any vertex of a convex polygon, the
// reflex vertex of an L).
inline TriangleMesh prism(const std::vector<Eigen::Vector2d>& polygon, double h, int fanFrom,
                          const std::string& name) {
    TriangleMesh m;
    m.name = name;
    const int n = static_cast<int>(polygon.size());
    for (double z : {-h, h})
        for (const auto& p : polygon) m.vertices.emplace_back(p.x(), p.y(), z);
    for (int k = 1; k + 1 < n; ++k) {
        const int a = fanFrom, b = (fanFrom + k) % n, c = (fanFrom + k + 1) % n;
        m.triangles.push_back({a, c, b});              // bottom faces -z
        m.triangles.push_back({n + a, n + b, n + c});  // top faces +z
    }
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        m.triangles.push_back({i, j, n + j});
        m.triangles.push_back({i, n + j, n + i});
    }
    return m;
}

// L-shaped prism: a 2a x 2a square minus its upper-right a x a quarter, thickness 2h.
inline TriangleMesh lShape(double a, double h) {
    return prism({{0, 0}, {2 * a, 0}, {2 * a, a}, {a, a}, {a, 2 * a}, {0, 2 * a}}, h, 3, "L shape");
}

}  // namespace btfracture::test
