// SPDX-License-Identifier: Zlib
// Principal axes of a mass-property tensor and libccd penetration (helpers the coupling uses).
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/geometry/ConvexHull.h>
#include <btFracture/geometry/ConvexPenetration.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace btfracture;

TEST(PrincipalAxes, RotatedOffsetBoxIsExact) {
    const Eigen::Vector3d h(0.2, 0.05, 0.3);
    TriangleMesh box = makeBox(h, 0.0, "box");
    const Eigen::AngleAxisd rotation(0.7, Eigen::Vector3d(1, 2, 3).normalized());
    const Eigen::Vector3d offset(5.0, -3.0, 2.0);
    for (auto& v : box.vertices) v = rotation * v + offset;
    const MassProperties mp = computeMassProperties(box);
    const double volume = 8.0 * h.prod();
    EXPECT_NEAR(mp.volume, volume, 1e-12 * volume);  // integrated about the origin, 5 m away
    // Rounding: the moments sum products of coordinates of size |offset|, so the centre is exact
    // to a few hundred ulps of |offset| (1.5e-13 m measured at -O2, below 1e-13 at -O3).
    EXPECT_LT((mp.centreOfMass - offset).norm(), 1e-12 * offset.norm());
    const Eigen::Vector3d d = 2.0 * h;
    const Eigen::Vector3d moments =
        volume / 12.0 *
        Eigen::Vector3d(d.y() * d.y() + d.z() * d.z(), d.x() * d.x() + d.z() * d.z(),
                        d.x() * d.x() + d.y() * d.y());
    const Eigen::Matrix3d expected =
        rotation.toRotationMatrix() * moments.asDiagonal() * rotation.toRotationMatrix().transpose();
    EXPECT_LT((mp.inertiaPerDensity - expected).norm(), 1e-10 * expected.norm());

    const PrincipalAxes axes = principalAxes(mp.inertiaPerDensity);
    EXPECT_NEAR(axes.rotation.determinant(), 1.0, 1e-12);
    EXPECT_LT((axes.rotation * axes.moments.asDiagonal() * axes.rotation.transpose() - expected).norm(),
              1e-10 * expected.norm());
    Eigen::Vector3d sorted = moments;
    std::sort(sorted.data(), sorted.data() + 3);
    EXPECT_LT((axes.moments - sorted).norm(), 1e-10 * sorted.norm());
}

TEST(ConvexPenetration, OverlappingBoxesHandComputed) {
    // Unit cubes centred at x = 0 and x = 0.8: they overlap by 0.2 along x.
    ConvexPolytope a{makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 0.0, "a").vertices, 0.0};
    ConvexPolytope b = a;
    for (auto& p : b.points) p.x() += 0.8;
    Penetration pen = convexPenetration(a, b);
    ASSERT_TRUE(pen.overlapping);
    EXPECT_NEAR(pen.depth, 0.2, 1e-6);
    EXPECT_NEAR(std::abs(pen.direction.x()), 1.0, 1e-6);
    // Moving b by depth along direction separates them (touching).
    ConvexPolytope moved = b;
    for (auto& p : moved.points) p += (pen.depth + 1e-6) * pen.direction;
    EXPECT_FALSE(convexPenetration(a, moved).overlapping);

    // Margins count: with 0.05 each, the overlap is 0.3.
    a.margin = b.margin = 0.05;
    pen = convexPenetration(a, b);
    EXPECT_NEAR(pen.depth, 0.3, 1e-6);

    // Apart: no overlap.
    a.margin = b.margin = 0.0;
    for (auto& p : b.points) p.x() += 0.5;
    EXPECT_FALSE(convexPenetration(a, b).overlapping);
    EXPECT_THROW(convexPenetration(ConvexPolytope{}, b), Error);
}
