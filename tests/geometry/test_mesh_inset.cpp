// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/geometry/MeshInset.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace btfracture;

namespace {

// Largest |coordinate| per axis of a mesh's vertices.
Eigen::Vector3d extents(const TriangleMesh& mesh) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    for (const auto& v : mesh.vertices) e = e.cwiseMax(v.cwiseAbs());
    return e;
}

}  // namespace

// Every face of a box moves in by d: corners along their diagonal, edge and face vertices
// across their faces.
TEST(MeshInset, BoxFacesMoveInByTheDistance) {
    const Eigen::Vector3d half(0.2, 0.1, 0.05);
    const TriangleMesh box = makeBox(half, 3, 2, 2);
    const double d = 0.004;
    const MeshInset inset = insetMesh(box, d);
    EXPECT_EQ(inset.reducedVertices, 0);
    EXPECT_GT(inset.smallestFraction, 0.99);
    for (std::size_t v = 0; v < box.vertices.size(); ++v)
        for (int axis = 0; axis < 3; ++axis) {
            const double before = box.vertices[v][axis];
            const double after = inset.mesh.vertices[v][axis];
            if (std::abs(std::abs(before) - half[axis]) < 1e-12)  // on a face normal to `axis`
                EXPECT_NEAR(std::abs(after), half[axis] - d, 1e-5 * d) << "vertex " << v << " axis " << axis;
            else
                EXPECT_NEAR(after, before, 1e-5 * d) << "vertex " << v << " axis " << axis;
        }
}

// A slab thinner than twice the distance is not turned inside out: its faces move in by less
// than half its thickness and keep their order.
TEST(MeshInset, ThinWallIsNotTurnedInsideOut) {
    const Eigen::Vector3d half(0.1, 0.1, 0.002);
    const TriangleMesh slab = makeBox(half, 4, 4, 1);
    const MeshInset inset = insetMesh(slab, 0.005);
    EXPECT_GT(inset.reducedVertices, 0);
    EXPECT_LT(inset.smallestFraction, 0.5);
    for (std::size_t v = 0; v < slab.vertices.size(); ++v) {
        const double before = slab.vertices[v].z(), after = inset.mesh.vertices[v].z();
        EXPECT_EQ(std::signbit(after), std::signbit(before)) << "vertex " << v << " crossed the mid-plane";
        EXPECT_LE(std::abs(after), std::abs(before) + 1e-12) << "vertex " << v;
    }
    EXPECT_LE(extents(inset.mesh).x(), half.x());
}

TEST(MeshInset, ZeroDistanceKeepsTheMeshAndBadDistancesAreRefused) {
    const TriangleMesh box = makeBox(Eigen::Vector3d(0.1, 0.1, 0.1), 0.0, "crate");
    EXPECT_EQ(insetMesh(box, 0.0).mesh.vertices, box.vertices);
    for (const double bad : {-0.001, std::nan("")}) {
        try {
            insetMesh(box, bad);
            ADD_FAILURE() << "distance " << bad << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("crate: inset distance"), std::string::npos) << e.what();
        }
    }
}
