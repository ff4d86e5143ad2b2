// SPDX-License-Identifier: Zlib
#pragma once
// Closed test meshes with known geometry, and the demo meshes scaled to a physical size.
#include <btFracture/core/Primitives.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/io/MeshReader.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace btfracture::test {

// Triangles of the fragments' collision meshes in these tests (LevelSetBody::fragments).
constexpr int kCollisionTriangles = 2000;

// Axis-aligned box [lo, hi], 12 outward triangles (core's makeBox, moved).
inline TriangleMesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                        const std::string& name = "box") {
    TriangleMesh m = makeBox(0.5 * (hi - lo));
    for (auto& v : m.vertices) v += 0.5 * (lo + hi);
    m.name = name;
    return m;
}

// Geodesic sphere of `radius` around `centre` with 20 * 4^levels triangles (core's primitive, moved).
inline TriangleMesh sphere(double radius, int levels,
                           const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
    TriangleMesh m = makeGeodesicSphere(radius, 1 << levels);
    for (auto& v : m.vertices) v += centre;
    m.name = "sphere";
    return m;
}

// Rectangle sheet through `centre` spanned by u and v (half extents), 2 triangles.
inline TriangleMesh sheet(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                          const std::string& name = "sheet") {
    TriangleMesh m;
    m.name = name;
    m.vertices = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// A demo mesh (demos/meshes) scaled uniformly so its longest bounding-box side is `size` metres
// and centred on its bounding box.
inline TriangleMesh demoMesh(const std::string& file, double size) {
    TriangleMesh m = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/" + file);
    Eigen::Vector3d lo = m.vertices.front(), hi = lo;
    for (const auto& p : m.vertices) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double scale = size / (hi - lo).maxCoeff();
    const Eigen::Vector3d mid = 0.5 * (lo + hi);
    for (auto& p : m.vertices) p = (p - mid) * scale;
    return m;
}

}  // namespace btfracture::test
