// SPDX-License-Identifier: Zlib
// Quadric edge-collapse decimation: closed, manifold, near the target, shape kept.
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/geometry/MeshDecimation.h>

#include <gtest/gtest.h>

namespace btfracture {
namespace {

TEST(MeshDecimation, SphereStaysClosedNearTargetAndKeepsVolume) {
    const TriangleMesh sphere = test::sphere(0.1, 5);  // 20480 triangles
    const TriangleMesh coarse = decimateMesh(sphere, 1000);
    const MeshDefects d = inspectMesh(coarse);
    EXPECT_TRUE(d.isClosedSolid()) << d.describe();
    EXPECT_LE(coarse.triangles.size(), 1000u);
    EXPECT_GE(coarse.triangles.size(), 990u);
    EXPECT_NEAR(d.signedVolume / computeMassProperties(sphere).volume, 1.0, 0.01);
    for (const auto& v : coarse.vertices) EXPECT_NEAR(v.norm(), 0.1, 0.002);
}

TEST(MeshDecimation, BoxCollapsesToFewTrianglesWithoutChangingShape) {
    const TriangleMesh box =
        decimateMesh(LevelSetBody(test::box({0, 0, 0}, {0.1, 0.06, 0.05}), 0.1 / 32).visualMesh(), 200);
    const MeshDefects d = inspectMesh(box);
    EXPECT_TRUE(d.isClosedSolid()) << d.describe();
    EXPECT_LE(box.triangles.size(), 200u);
    EXPECT_NEAR(d.signedVolume / 3e-4, 1.0, 0.03);
}

// Collision meshes are closed and manifold (bunny, armadillo).
TEST(MeshDecimation, CollisionMeshesOfBunnyAndArmadilloAreClosedManifolds) {
    for (const auto& [file, size] :
         {std::pair<const char*, double>{"bunny.obj", 0.15}, {"armadillo.obj", 0.3}}) {
        const TriangleMesh mesh = test::demoMesh(file, size);
        const LevelSetBody body(mesh, size / 96);  // coarser than the default: mesh checks only
        for (int target : {500, 2000}) {
            const TriangleMesh collision = body.collisionMesh(target);
            const MeshDefects d = inspectMesh(collision);
            EXPECT_TRUE(d.isClosedManifold()) << file << " " << target << ": " << d.describe();
            EXPECT_EQ(d.components, 1) << file;
            EXPECT_LE(static_cast<int>(collision.triangles.size()), target);
            EXPECT_GE(static_cast<int>(collision.triangles.size()), target - 10);
            EXPECT_NEAR(d.signedVolume / body.massProperties().volume, 1.0, target >= 2000 ? 0.03 : 0.06)
                << file;
        }
    }
}

TEST(MeshDecimation, BadTargetIsRejected) {
    EXPECT_THROW(decimateMesh(test::sphere(1, 1), 3), Error);
    EXPECT_EQ(decimateMesh(test::sphere(1, 1), 80).triangles.size(), 80u);  // already small enough
}

}  // namespace
}  // namespace btfracture
