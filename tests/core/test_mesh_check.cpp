// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MeshCheck.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace btfracture;

namespace {

TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.name = "tetra";
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

std::string errorOf(TriangleMesh m) {
    try {
        requireClosedSolid(m);
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(MeshCheck, ClosedTetrahedronIsClean) {
    const MeshDefects d = inspectMesh(tetrahedron());
    EXPECT_TRUE(d.isClosedManifold()) << d.describe();
    EXPECT_EQ(d.components, 1);
    EXPECT_NEAR(d.signedVolume, 1.0 / 6.0, 1e-15);
}

TEST(MeshCheck, OpenMeshReportsBoundaryEdges) {
    TriangleMesh m = tetrahedron();
    m.triangles.pop_back();
    EXPECT_EQ(inspectMesh(m).boundaryEdges, 3);
    const std::string message = errorOf(m);
    EXPECT_NE(message.find("tetra"), std::string::npos) << message;
    EXPECT_NE(message.find("3 boundary edges"), std::string::npos) << message;
}

TEST(MeshCheck, NonManifoldEdgeAndVertex) {
    TriangleMesh m = tetrahedron();
    // A fin hanging off edge (0,1): that edge now has three triangles.
    m.vertices.push_back({0.5, -1, 0});
    m.triangles.push_back({0, 4, 1});
    EXPECT_EQ(inspectMesh(m).nonManifoldEdges, 1);

    // Two tetrahedra touching in one vertex: the shared vertex has two fans.
    TriangleMesh bowtie = tetrahedron();
    for (int i = 1; i < 4; ++i) bowtie.vertices.push_back(-bowtie.vertices[i]);
    bowtie.triangles.push_back({0, 4, 5});
    bowtie.triangles.push_back({0, 6, 4});
    bowtie.triangles.push_back({0, 5, 6});
    bowtie.triangles.push_back({4, 6, 5});
    const MeshDefects d = inspectMesh(bowtie);
    EXPECT_EQ(d.nonManifoldVertices, 1);
    EXPECT_EQ(d.components, 2);
    EXPECT_NE(errorOf(bowtie).find("1 non-manifold vertex"), std::string::npos);
}

TEST(MeshCheck, InconsistentOrientation) {
    TriangleMesh m = tetrahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    EXPECT_EQ(inspectMesh(m).inconsistentEdges, 3);
    EXPECT_NE(errorOf(m).find("3 inconsistently oriented edges"), std::string::npos);
}

TEST(MeshCheck, DegenerateAndNonFinite) {
    TriangleMesh flat = tetrahedron();
    flat.vertices[3] = {0.25, 0.25,
                        0.0};  // all four points coplanar: every face has zero volume, one has zero area
    flat.vertices[2] = {0.5, 0.0, 0.0};  // collinear with 0 and 1
    EXPECT_GE(inspectMesh(flat).degenerateTriangles, 1);

    TriangleMesh nan = tetrahedron();
    nan.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
    const std::string message = errorOf(nan);
    EXPECT_NE(message.find("1 non-finite vertex"), std::string::npos) << message;

    TriangleMesh bad = tetrahedron();
    bad.triangles[0][0] = 17;
    EXPECT_NE(errorOf(bad).find("invalid vertex ind"), std::string::npos);

    TriangleMesh empty;
    empty.name = "nothing.obj";
    EXPECT_NE(errorOf(empty).find("nothing.obj: mesh has no triangles"), std::string::npos);
}

TEST(MeshCheck, InsideOutIsFlippedWithWarning) {
    TriangleMesh m = tetrahedron();
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    EXPECT_LT(inspectMesh(m).signedVolume, 0.0);
    std::string warning;
    setLogSink([&](LogLevel level, const std::string& text) {
        if (level == LogLevel::Warning) warning = text;
    });
    requireClosedSolid(m);
    setLogSink(nullptr);
    EXPECT_NEAR(inspectMesh(m).signedVolume, 1.0 / 6.0, 1e-15);
    EXPECT_NE(warning.find("inside-out"), std::string::npos) << warning;
}
