// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace btfracture;

namespace {

// Axis-aligned box [x0, x0 + a] x [y0, y0 + b] x [z0, z0 + c], outward triangles.
TriangleMesh box(double a, double b, double c, const Eigen::Vector3d& origin) {
    TriangleMesh m;
    m.name = "box";
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back(origin + Eigen::Vector3d((i & 1) * a, ((i >> 1) & 1) * b, ((i >> 2) & 1) * c));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

}  // namespace

TEST(MassProperties, BoxMatchesClosedForm) {
    const double a = 2.0, b = 0.5, c = 1.5;
    const Eigen::Vector3d origin(3.0, -1.0, 7.0);
    const MassProperties p = computeMassProperties(box(a, b, c, origin));
    const double V = a * b * c;
    EXPECT_NEAR(p.volume, V, 1e-12);
    EXPECT_LT((p.centreOfMass - (origin + Eigen::Vector3d(a, b, c) / 2)).norm(), 1e-12);
    // I_xx = V (b^2 + c^2) / 12 about the centre, off-diagonals zero.
    EXPECT_NEAR(p.inertiaPerDensity(0, 0), V * (b * b + c * c) / 12, 1e-12);
    EXPECT_NEAR(p.inertiaPerDensity(1, 1), V * (a * a + c * c) / 12, 1e-12);
    EXPECT_NEAR(p.inertiaPerDensity(2, 2), V * (a * a + b * b) / 12, 1e-12);
    EXPECT_NEAR(p.inertiaPerDensity(0, 1), 0.0, 1e-12);
    EXPECT_NEAR(p.inertiaPerDensity(1, 2), 0.0, 1e-12);
}

TEST(MassProperties, InsideOutMeshIsRejected) {
    TriangleMesh m = box(1, 1, 1, Eigen::Vector3d::Zero());
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    EXPECT_THROW(computeMassProperties(m), Error);
}

TEST(MassProperties, PrincipalAxesDiagonaliseARotatedBox) {
    // A box turned 30 degrees about z and 50 about x has a full inertia tensor in the mesh frame;
    // its principal moments are the box's closed-form ones and the frame is a proper rotation.
    const double a = 2.0, b = 0.5, c = 1.5;
    TriangleMesh m = box(a, b, c, Eigen::Vector3d(-1.0, -0.25, -0.75));
    const Eigen::Matrix3d turn = (Eigen::AngleAxisd(0.5236, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(0.8727, Eigen::Vector3d::UnitX()))
                                     .matrix();
    for (auto& v : m.vertices) v = turn * v;
    const MassProperties p = computeMassProperties(m);
    EXPECT_GT(std::abs(p.inertiaPerDensity(0, 1)), 1e-3);
    const PrincipalAxes axes = principalAxes(p.inertiaPerDensity);
    const double V = a * b * c;
    EXPECT_NEAR(axes.moments[0], V * (b * b + c * c) / 12, 1e-12);  // about the long x edge: smallest
    EXPECT_NEAR(axes.moments[1], V * (a * a + b * b) / 12, 1e-12);  // about z
    EXPECT_NEAR(axes.moments[2], V * (a * a + c * c) / 12, 1e-12);  // about the short y edge: largest
    EXPECT_NEAR(axes.rotation.determinant(), 1.0, 1e-12);
    const Eigen::Matrix3d back = axes.rotation * axes.moments.asDiagonal() * axes.rotation.transpose();
    EXPECT_LT((back - p.inertiaPerDensity).norm(), 1e-12);
    // The principal axis of the smallest moment is the box's own x axis, turned.
    EXPECT_NEAR(std::abs(axes.rotation.col(0).dot(turn.col(0))), 1.0, 1e-12);
    EXPECT_THROW(principalAxes(Eigen::Matrix3d::Constant(NAN)), Error);
}
