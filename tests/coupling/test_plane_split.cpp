// SPDX-License-Identifier: Zlib
#include "TestMeshes.h"

#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/dynamics/PlaneSplitFractureEngine.h>
#include <btFracture/geometry/ConvexHull.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace btfracture;

TEST(PlaneSplit, BoxHalvesAreClosedAndExact) {
    const Eigen::Vector3d h(0.2, 0.025, 0.2);
    const TriangleMesh box = makeBox(h, 0.0, "slab");
    const MassProperties whole = computeMassProperties(box);
    // An oblique plane through an off-centre point.
    const Eigen::Vector3d p(0.05, 0.01, -0.03), n = Eigen::Vector3d(0.3, 0.1, 1.0).normalized();
    const auto [a, b] = splitConvexMesh(box, p, n);
    for (const TriangleMesh* half : {&a, &b}) {
        const MeshDefects d = inspectMesh(*half);
        EXPECT_TRUE(d.isClosedManifold()) << d.describe();
        EXPECT_GT(d.signedVolume, 0.0);
        EXPECT_TRUE(isConvex(*half));
    }
    for (const auto& v : a.vertices) EXPECT_GE(n.dot(v - p), -1e-12);
    for (const auto& v : b.vertices) EXPECT_LE(n.dot(v - p), 1e-12);
    const MassProperties ma = computeMassProperties(a), mb = computeMassProperties(b);
    EXPECT_NEAR(ma.volume + mb.volume, whole.volume, 1e-14 * whole.volume);
    // First moments and inertia (parallel axis) add up to the whole.
    EXPECT_LT((ma.volume * ma.centreOfMass + mb.volume * mb.centreOfMass).norm(), 1e-14);
    auto shifted = [](const MassProperties& m) {
        const Eigen::Vector3d c = m.centreOfMass;
        return Eigen::Matrix3d(m.inertiaPerDensity +
                               m.volume *
                                   (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose()));
    };
    EXPECT_LT((shifted(ma) + shifted(mb) - whole.inertiaPerDensity).norm(),
              1e-12 * whole.inertiaPerDensity.norm());
}

TEST(PlaneSplit, AxisAlignedCutThroughVerticesAndMisses) {
    const TriangleMesh box = makeBox(Eigen::Vector3d(1, 1, 1), 0.0, "cube");
    // Through the middle: two exact halves of volume 4 (the cut crosses the face diagonals).
    auto [a, b] = splitConvexMesh(box, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
    EXPECT_NEAR(computeMassProperties(a).volume, 4.0, 1e-12);
    EXPECT_NEAR(computeMassProperties(b).volume, 4.0, 1e-12);
    // A plane through a vertex is nudged off it and still gives closed halves.
    auto [c, d] = splitConvexMesh(box, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 1));
    EXPECT_TRUE(c.triangles.empty() || inspectMesh(c).isClosedManifold());
    EXPECT_TRUE(inspectMesh(d).isClosedManifold());
    // A plane beyond the body leaves one side empty.
    auto [e, f] = splitConvexMesh(box, Eigen::Vector3d(3, 0, 0), Eigen::Vector3d::UnitX());
    EXPECT_TRUE(e.triangles.empty());
    EXPECT_EQ(f.triangles.size(), box.triangles.size());
}
