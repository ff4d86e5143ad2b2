// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/SelfIntersection.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace btfracture;

namespace {

// Two loose triangles given by six corners (no shared indices unless `shareFrom` says so).
TriangleMesh pair(const std::array<Eigen::Vector3d, 3>& a, const std::array<Eigen::Vector3d, 3>& b) {
    TriangleMesh m;
    m.name = "pair";
    for (const auto& p : a) m.vertices.push_back(p);
    for (const auto& p : b) m.vertices.push_back(p);
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    return m;
}

size_t count(const TriangleMesh& m) {
    return findSelfIntersections(m).size();
}

TriangleMesh tetrahedron(const Eigen::Vector3d& shift, int firstIndex) {
    TriangleMesh m;
    m.vertices = {shift + Eigen::Vector3d(0, 0, 0), shift + Eigen::Vector3d(1, 0, 0),
                  shift + Eigen::Vector3d(0, 1, 0), shift + Eigen::Vector3d(0, 0, 1)};
    const int o = firstIndex;
    m.triangles = {{o, o + 2, o + 1}, {o, o + 1, o + 3}, {o, o + 3, o + 2}, {o + 1, o + 2, o + 3}};
    return m;
}

TriangleMesh twoTetrahedra(const Eigen::Vector3d& shift) {
    TriangleMesh m = tetrahedron(Eigen::Vector3d::Zero(), 0);
    const TriangleMesh second = tetrahedron(shift, 4);
    m.vertices.insert(m.vertices.end(), second.vertices.begin(), second.vertices.end());
    m.triangles.insert(m.triangles.end(), second.triangles.begin(), second.triangles.end());
    m.name = "two-tetrahedra";
    return m;
}

// Closed UV sphere with `rings` x `segments` quads split into triangles, outward-facing.
TriangleMesh uvSphere(int rings, int segments) {
    TriangleMesh m;
    m.name = "uv-sphere";
    m.vertices.push_back({0, 0, 1});
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
            m.vertices.push_back(
                {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    m.vertices.push_back({0, 0, -1});
    const int south = static_cast<int>(m.vertices.size()) - 1;
    auto ring = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    for (int r = 1; r < rings - 1; ++r)
        for (int s = 0; s < segments; ++s) {
            m.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
            m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
        }
    for (int s = 0; s < segments; ++s)
        m.triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
    return m;
}

}  // namespace

TEST(SelfIntersection, LooseTrianglePairs) {
    using V = Eigen::Vector3d;
    // Crossing like an X: triangle b pierces a through its interior.
    EXPECT_EQ(
        count(pair({V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)}, {V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(1.5, 1.5, 0)})),
        1u);
    // Parallel planes 0.1 apart: no contact.
    EXPECT_EQ(count(pair({V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)}, {V(0, 0, 0.1), V(2, 0, 0.1), V(0, 2, 0.1)})),
              0u);
    // Crossing the plane, but outside the other triangle.
    EXPECT_EQ(count(pair({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {V(2, 2, -1), V(2, 2, 1), V(3, 3, 0)})), 0u);
    // Coplanar overlap, coplanar apart, coplanar one inside the other.
    EXPECT_EQ(count(pair({V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)}, {V(1, 1, 0), V(-1, 1, 0), V(1, -1, 0)})), 1u);
    EXPECT_EQ(count(pair({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {V(2, 2, 0), V(3, 2, 0), V(2, 3, 0)})), 0u);
    EXPECT_EQ(count(pair({V(0, 0, 0), V(4, 0, 0), V(0, 4, 0)}, {V(1, 1, 0), V(2, 1, 0), V(1, 2, 0)})), 1u);
    // A corner touching the other's face counts (a solid must not touch itself).
    EXPECT_EQ(
        count(pair({V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)}, {V(0.5, 0.5, 0), V(0.5, 0.5, 1), V(1, 0.5, 1)})),
        1u);
}

TEST(SelfIntersection, NeighboursSharingAVertex) {
    TriangleMesh m;
    m.name = "fan";
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0.2}, {0, -1, 0.2}};
    m.triangles = {{0, 1, 2}, {0, 3, 4}};  // an ordinary fan: only the shared vertex in common
    EXPECT_EQ(count(m), 0u);
    m.vertices[3] = {0.5, 0.2, -1};  // now the second triangle pierces the first
    m.vertices[4] = {0.2, 0.5, 1};
    EXPECT_EQ(count(m), 1u);
    m.vertices[3] = {1, 1, 0};  // coplanar, overlapping wedges
    m.vertices[4] = {2, 0.5, 0};
    EXPECT_EQ(count(m), 1u);
}

TEST(SelfIntersection, NeighboursSharingAnEdge) {
    TriangleMesh m;
    m.name = "hinge";
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.3}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}};  // an ordinary hinge
    EXPECT_EQ(count(m), 0u);
    m.vertices[3] = {0.5, -1, 0};  // flat hinge: still fine
    EXPECT_EQ(count(m), 0u);
    m.vertices[3] = {0.3, 0.5, 0};  // folded flat onto the first triangle
    EXPECT_EQ(count(m), 1u);
    m.triangles.push_back({0, 2, 1});  // the same three vertices twice
    EXPECT_EQ(count(m), 3u);
}

TEST(SelfIntersection, ClosedMeshes) {
    EXPECT_EQ(count(tetrahedron(Eigen::Vector3d::Zero(), 0)), 0u);
    EXPECT_EQ(count(twoTetrahedra({2, 0, 0})), 0u);
    // Overlapping copies: each face of one crosses faces of the other.
    const TriangleMesh overlap = twoTetrahedra({0.25, 0.25, 0.25});
    const MeshDefects d = inspectMesh(overlap);
    EXPECT_TRUE(d.isClosedManifold());
    EXPECT_GT(d.intersectingPairs, 0);
    EXPECT_FALSE(d.isClosedSolid());
    TriangleMesh copy = overlap;
    try {
        requireClosedSolid(copy);
        FAIL() << "self-intersecting mesh accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("two-tetrahedra"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(d.intersectingPairs) + " self-intersecting triangle pairs"),
                  std::string::npos)
            << message;
    }
}

TEST(SelfIntersection, FineSphereIsClean) {
    // 50k triangles with many vertex-sharing neighbours, including the long thin pole fans.
    const TriangleMesh sphere = uvSphere(161, 157);
    ASSERT_GT(sphere.triangles.size(), 50000u);
    EXPECT_EQ(count(sphere), 0u);
    // Push one vertex through the opposite side: its fan now crosses the far wall.
    TriangleMesh dented = sphere;
    dented.vertices[1 + 80 * 157] *= -1.5;
    EXPECT_GT(count(dented), 0u);
}

// A triangle with a repeated corner is degenerate and takes no part in the test, even when a
// compiler's fused multiply-adds leave its cross-product normal a rounding error away from zero
// (a fuzzing find: the shared-corner bookkeeping then indexed outside the triangle).
TEST(SelfIntersection, RepeatedCornersAreSkipped) {
    TriangleMesh m;
    m.vertices = {{0.25, 0.25, 0.1}, {0.15, 0.15, -0.2}, {0.4, 0.15, -0.2}, {0.15, 0.4, -0.2}};
    m.triangles = {{1, 3, 2}, {0, 2, 2}, {0, 2, 3}, {0, 3, 1}, {2, 2, 2}};
    EXPECT_EQ(count(m), 0u);
}
