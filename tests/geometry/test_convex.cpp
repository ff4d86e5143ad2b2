// SPDX-License-Identifier: Zlib
// Convex hulls (exact quickhull) and the penetration between hulls (GJK + EPA).
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/geometry/ConvexClip.h>
#include <btFracture/geometry/ConvexHull.h>
#include <btFracture/geometry/ConvexPenetration.h>
#include <btFracture/geometry/HullSimplification.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

namespace btfracture {
namespace {

std::vector<Eigen::Vector3d> boxCorners(const Eigen::Vector3d& half) {
    return test::box(-half, half).vertices;
}

// Every point lies on or inside every face plane of the hull.
void expectContains(const TriangleMesh& hull, const std::vector<Eigen::Vector3d>& points, double tolerance) {
    for (const auto& t : hull.triangles) {
        const Eigen::Vector3d& a = hull.vertices[t[0]];
        const Eigen::Vector3d n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
        for (const auto& p : points) ASSERT_LE((p - a).dot(n), tolerance);
    }
}

// The hull of `points` is the box of volume `volume` spanned by eight of them.
void expectBoxHull(const std::vector<Eigen::Vector3d>& points, double volume, double tolerance) {
    const TriangleMesh hull = convexHullMesh(points, "box");
    EXPECT_EQ(hull.vertices.size(), 8u);
    const MeshDefects d = inspectMesh(hull);
    EXPECT_TRUE(d.isClosedManifold()) << d.describe();
    EXPECT_NEAR(d.signedVolume, volume, tolerance);
    expectContains(hull, points, tolerance);
}

TEST(ConvexHull, BoxWithInteriorPointsIsTheBox) {
    std::vector<Eigen::Vector3d> points = boxCorners({0.1, 0.2, 0.3});
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 500; ++i) points.emplace_back(0.1 * u(rng), 0.2 * u(rng), 0.3 * u(rng));
    expectBoxHull(points, 0.2 * 0.4 * 0.6, 1e-12);
    for (const auto& v : convexHullMesh(points, "box cloud").vertices)
        EXPECT_EQ(v.cwiseAbs(), Eigen::Vector3d(0.1, 0.2, 0.3));  // input points, exactly
}

TEST(ConvexHull, SphereHullContainsAllPoints) {
    const TriangleMesh sphere = test::sphere(0.05, 3);
    const TriangleMesh hull = convexHullMesh(sphere.vertices, "sphere");
    EXPECT_TRUE(inspectMesh(hull).isClosedManifold());
    EXPECT_EQ(hull.vertices.size(), sphere.vertices.size());
    expectContains(hull, sphere.vertices, 1e-12);
}

// Lattice points are coplanar and collinear in every direction and each one is given twice:
// every orientation test there is exact, and the hull is still the box of the corners.
TEST(ConvexHull, LatticeWithDuplicatesIsItsBoundingBox) {
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 3; ++k) {
                points.emplace_back(0.1 * i, 0.1 * j, 0.1 * k);
                points.emplace_back(0.1 * i, 0.1 * j, 0.1 * k);
            }
    expectBoxHull(points, 0.4 * 0.3 * 0.2, 1e-15);
}

// Voxel corners of an ellipsoid (what a thin fragment's hull is made of): closed, convex, holds
// every corner.
TEST(ConvexHull, VoxelCornersOfAnEllipsoid) {
    std::vector<Eigen::Vector3d> points;
    const Eigen::Vector3d origin(0.1234, -0.77, 0.3);
    const double voxel = 0.013;
    for (int i = -20; i <= 20; ++i)
        for (int j = -15; j <= 15; ++j)
            for (int k = -8; k <= 8; ++k) {
                if (i * i / 400.0 + j * j / 225.0 + k * k / 64.0 > 1.0) continue;
                for (int c = 0; c < 8; ++c)
                    points.push_back(origin + voxel * Eigen::Vector3d(i + (c & 1 ? 0.5 : -0.5),
                                                                      j + (c & 2 ? 0.5 : -0.5),
                                                                      k + (c & 4 ? 0.5 : -0.5)));
            }
    const TriangleMesh hull = convexHullMesh(points, "voxels");
    const MeshDefects d = inspectMesh(hull);
    EXPECT_TRUE(d.isClosedManifold()) << d.describe();
    EXPECT_TRUE(isConvex(hull));
    expectContains(hull, points, 1e-15);
    EXPECT_EQ(convexHullMesh(points, "voxels").vertices, hull.vertices);  // deterministic
}

// Points within a grid cell (2^-40 of the box's largest side) of a face plane snap onto it: the
// hull stays the box of the eight corners, and holds every point up to that cell.
TEST(ConvexHull, PointsWithinAGridCellOfAFaceAreNotCorners) {
    std::vector<Eigen::Vector3d> points = boxCorners({0.1, 0.2, 0.3});
    const double cell = std::ldexp(0.6, -40);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i)
        points.emplace_back(0.09 * u(rng), 0.19 * u(rng), 0.3 + 0.4 * cell * u(rng));
    expectBoxHull(points, 0.2 * 0.4 * 0.6, 1e-12);
    expectContains(convexHullMesh(points, "box"), points, cell);
}

TEST(ConvexHull, DegenerateInputIsRejected) {
    EXPECT_THROW(convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "three points"), Error);
    EXPECT_THROW(convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}}, "flat"), Error);
    EXPECT_THROW(convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}}, "nan"), Error);
    EXPECT_THROW(convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1e301}}, "huge"), Error);
    // Thinner than a grid cell (2^-40 of the largest side) is flat.
    EXPECT_THROW(convexHullMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1e-14}}, "sliver"), Error);
    EXPECT_TRUE(isConvex(convexHullMesh(test::sphere(1.0, 2).vertices, "sphere")));
    EXPECT_FALSE(isConvex(test::demoMesh("bunny.obj", 0.15)));
}

// Largest distance of `points` outside the hull mesh (0 when all are inside).
double largestDistanceOutside(const TriangleMesh& hull, const std::vector<Eigen::Vector3d>& points) {
    double largest = 0.0;
    for (const auto& p : points)
        for (const auto& t : hull.triangles) {
            const Eigen::Vector3d a = hull.vertices[t[0]];
            const Eigen::Vector3d n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
            largest = std::max(largest, n.dot(p - a));
        }
    return largest;
}

// A box sampled on its faces and inside keeps exactly its eight corners under any budget >= 8.
TEST(HullBudget, BoxKeepsItsCorners) {
    std::vector<Eigen::Vector3d> points;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 600; ++i) {
        Eigen::Vector3d p(u(rng), u(rng), u(rng));
        p[i % 3] = i % 2 ? 1.0 : -1.0;  // on a face
        points.push_back(p.cwiseProduct(Eigen::Vector3d(0.1, 0.2, 0.3)));
    }
    for (const auto& corner : boxCorners({0.1, 0.2, 0.3})) points.push_back(corner);
    const std::vector<Eigen::Vector3d> kept = budgetHullPoints(points, 16);
    EXPECT_EQ(kept.size(), 8u);
    expectBoxHull(kept, 0.2 * 0.4 * 0.6, 1e-12);
    EXPECT_EQ(budgetHullPoints(points, 0).size(), points.size());  // 0: no budget
}

// A round chip (642 sphere vertices) kept to 48 corners: at most 48, all of them input points,
// inside the full hull by construction, and no input point farther than 10 % of the radius
// outside the kept hull. A sphere is the worst case for an inscribed polytope: 48 ideally spread
// corners (a cell of 4 pi / 48 sr each, covering radius ~0.32 rad) leave caps of
// R (1 - cos 0.32) = 5 % R; the Fibonacci lattice's cells are up to ~1.4 times wider, hence
// 10 %. Fragments are mostly flat cut faces, which keep their corners (test above).
TEST(HullBudget, RoundChipStaysFaithful) {
    const double radius = 0.05;
    const TriangleMesh sphere = test::sphere(radius, 3);
    ASSERT_GT(sphere.vertices.size(), 48u);
    const std::vector<Eigen::Vector3d> kept = budgetHullPoints(sphere.vertices, 48);
    EXPECT_LE(kept.size(), 48u);
    EXPECT_GE(kept.size(), 40u);
    for (const auto& p : kept)
        EXPECT_NE(std::find(sphere.vertices.begin(), sphere.vertices.end(), p), sphere.vertices.end());
    const TriangleMesh hull = convexHullMesh(kept, "kept");
    EXPECT_LT(largestDistanceOutside(hull, sphere.vertices), 0.10 * radius);
    EXPECT_EQ(budgetHullPoints(sphere.vertices, 48), kept);  // deterministic
}

// Places hull points (own frame) in the world.
ConvexPolytope placed(const std::vector<Eigen::Vector3d>& points, const Eigen::Isometry3d& pose) {
    ConvexPolytope p;
    for (const auto& v : points) p.points.push_back(pose * v);
    return p;
}

// The penetration depth between two overlapping box hulls matches the hand-computed value.
TEST(ConvexPenetration, OverlappingBoxHullsGiveHandComputedDepth) {
    const auto unit = convexHullMesh(boxCorners({0.5, 0.5, 0.5}), "unit box").vertices;
    const ConvexPolytope a = placed(unit, Eigen::Isometry3d::Identity());
    // B shifted by (0.8, 0.1, 0.05): overlaps are 0.2 in x, 0.9 in y, 0.95 in z -> depth 0.2 along x.
    Eigen::Isometry3d poseB = Eigen::Isometry3d::Identity();
    poseB.translation() = Eigen::Vector3d(0.8, 0.1, 0.05);
    Penetration c = convexPenetration(a, placed(unit, poseB));
    ASSERT_TRUE(c.overlapping);
    EXPECT_NEAR(c.depth, 0.2, 1e-6);
    EXPECT_NEAR(c.direction.x(), 1.0, 1e-6);  // moving B by +x separates
    EXPECT_GT(c.point.x(), 0.3 - 1e-6);       // contact inside the overlap region
    EXPECT_LT(c.point.x(), 0.5 + 1e-6);

    // B turned 45 degrees about z at x = 1.1: its edge reaches x = 1.1 - sqrt(2)/2, so the depth
    // is 0.5 + sqrt(2)/2 - 1.1 = 0.10711 along x (along the diagonal it would be 0.4293).
    poseB = Eigen::Isometry3d::Identity();
    poseB.translation() = Eigen::Vector3d(1.1, 0.0, 0.0);
    poseB.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    c = convexPenetration(a, placed(unit, poseB));
    ASSERT_TRUE(c.overlapping);
    EXPECT_NEAR(c.depth, 0.5 + std::sqrt(0.5) - 1.1, 1e-6);
    EXPECT_NEAR(c.direction.x(), 1.0, 1e-6);
    // Translating B by the result separates the hulls.
    Eigen::Isometry3d moved = poseB;
    moved.translation() += (c.depth + 1e-6) * c.direction;
    EXPECT_FALSE(convexPenetration(a, placed(unit, moved)).overlapping);
}

TEST(ConvexPenetration, SeparatedHullsDoNotOverlap) {
    const auto unit = boxCorners({0.5, 0.5, 0.5});
    Eigen::Isometry3d poseB = Eigen::Isometry3d::Identity();
    poseB.translation() = Eigen::Vector3d(1.2, 0.0, 0.0);
    const Penetration c = convexPenetration(placed(unit, Eigen::Isometry3d::Identity()), placed(unit, poseB));
    EXPECT_FALSE(c.overlapping);
    EXPECT_EQ(c.depth, 0.0);
}

// Exact minimal translation of b out of a for bare polytopes, by the separating axes: the face
// normals of both hulls and the cross products of their edges. Returns (depth, direction).
std::pair<double, Eigen::Vector3d> satDepth(const std::vector<Eigen::Vector3d>& a,
                                            const std::vector<Eigen::Vector3d>& b) {
    const TriangleMesh ha = convexHullMesh(a, "a"), hb = convexHullMesh(b, "b");
    std::vector<Eigen::Vector3d> axes;
    std::vector<Eigen::Vector3d> edgesA, edgesB;
    for (const TriangleMesh* h : {&ha, &hb})
        for (const auto& t : h->triangles) {
            const Eigen::Vector3d& p = h->vertices[t[0]];
            axes.push_back((h->vertices[t[1]] - p).cross(h->vertices[t[2]] - p).normalized());
            for (int k = 0; k < 3; ++k)
                (h == &ha ? edgesA : edgesB).push_back(h->vertices[t[(k + 1) % 3]] - h->vertices[t[k]]);
        }
    for (const auto& ea : edgesA)
        for (const auto& eb : edgesB) {
            const Eigen::Vector3d n = ea.cross(eb);
            if (n.norm() > 1e-9 * ea.norm() * eb.norm()) axes.push_back(n.normalized());
        }
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    for (const auto& axis : axes)
        for (const double sign : {1.0, -1.0}) {
            const Eigen::Vector3d d = sign * axis;
            double maxA = -std::numeric_limits<double>::infinity(),
                   minB = std::numeric_limits<double>::infinity();
            for (const auto& p : a) maxA = std::max(maxA, p.dot(d));
            for (const auto& p : b) minB = std::min(minB, p.dot(d));
            if (maxA - minB < best) {
                best = maxA - minB;
                direction = d;
            }
        }
    return {best, direction};
}

// Random polytopes (8-40 points in flattened ellipsoids, some points repeated, some on a common
// plane) in random overlapping poses, with and without margins: the depth is the separating-axis
// minimum to 1e-9 of their size, and moving b by it along the direction leaves them touching.
// Pieces of one box cut by a plane (sharing a face, or pushed 1e-7 into each other) too: the case
// libccd's EPA looped on for ever (danfis/libccd#7) came from such pieces.
TEST(ConvexPenetration, DepthIsTheSeparatingAxisMinimum) {
    std::mt19937 rng(20261207);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto randomPoints = [&](int n) {
        const Eigen::Vector3d axes(0.1 + 0.9 * std::abs(unit(rng)), 0.1 + 0.9 * std::abs(unit(rng)),
                                   0.05 + 0.5 * std::abs(unit(rng)));
        std::vector<Eigen::Vector3d> points;
        for (int i = 0; i < n; ++i) {
            Eigen::Vector3d p(unit(rng), unit(rng), unit(rng));
            if (i % 5 == 4) p.z() = 1.0;  // a common plane
            points.push_back(p.normalized().cwiseProduct(axes));
            if (i % 7 == 6) points.push_back(points.back());  // a repeated point
        }
        return points;
    };
    int overlapping = 0;
    for (int trial = 0; trial < 150; ++trial) {
        const std::vector<Eigen::Vector3d> a = randomPoints(8 + trial % 33);
        std::vector<Eigen::Vector3d> b = randomPoints(8 + (trial * 7) % 33);
        const Eigen::Quaterniond turn =
            Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
        const Eigen::Vector3d shift = 0.8 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
        for (auto& p : b) p = turn * p + shift;
        const auto [reference, axis] = satDepth(a, b);
        for (const double margin : {0.0, 0.01}) {
            const Penetration pen = convexPenetration({a, margin}, {b, margin});
            const double expected = reference + 2.0 * margin;
            ASSERT_EQ(pen.overlapping, expected > 1e-9) << trial << " " << expected;
            if (!pen.overlapping || reference < 0.0) continue;
            ++overlapping;
            EXPECT_NEAR(pen.depth, expected, 1e-9) << trial;
            EXPECT_NEAR(pen.direction.norm(), 1.0, 1e-12);
            std::vector<Eigen::Vector3d> moved = b;
            for (auto& p : moved) p += (pen.depth - 2.0 * margin + 1e-7) * pen.direction;
            const double left = satDepth(a, moved).first;
            EXPECT_GT(left, -2e-7) << trial;  // touching, not apart
            EXPECT_LT(left, 0.0) << trial;    // nor still inside
        }
    }
    EXPECT_GT(overlapping, 100);

    // Two pieces of a box cut by an oblique plane: touching (depth = the margins), and pushed
    // 1e-7 into each other along the cut's normal.
    const std::vector<Eigen::Vector3d> box = boxCorners({0.05, 0.03, 0.02});
    const Eigen::Vector3d n = Eigen::Vector3d(1.0, 0.3, -0.2).normalized();
    const ConvexPolytope whole{box, 0.0};
    const ConvexPolytope left = clipConvexPolytope(whole, n, 0.004).polytope;
    const ConvexPolytope right = clipConvexPolytope(whole, -n, -0.004).polytope;
    for (const double margin : {0.0, 0.001}) {
        const Penetration touching = convexPenetration({left.points, margin}, {right.points, margin});
        if (margin > 0.0) {
            ASSERT_TRUE(touching.overlapping);
            EXPECT_NEAR(touching.depth, 2.0 * margin, 1e-12);
            EXPECT_NEAR(touching.direction.dot(n), 1.0, 1e-9);
        }
        std::vector<Eigen::Vector3d> pushed = right.points;
        for (auto& p : pushed) p -= 1e-7 * n;
        const Penetration in = convexPenetration({left.points, margin}, {pushed, margin});
        ASSERT_TRUE(in.overlapping);
        EXPECT_NEAR(in.depth, 1e-7 + 2.0 * margin, 1e-12);
        EXPECT_NEAR(in.direction.dot(n), 1.0, 1e-9);
    }
}

TEST(ConvexClip, CutBoxKeepsItsPartAndReportsItsVolume) {
    // The unit box cut by the plane x + y = 0.5 (margin 0): the prism below it keeps
    // 1 - (0.5^2 / 2) of the volume; along x alone at 0.25, three quarters.
    ConvexPolytope box{boxCorners({0.5, 0.5, 0.5}), 0.0};
    const Eigen::Vector3d diagonal = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
    const ClippedPolytope corner = clipConvexPolytope(box, diagonal, 0.5 / std::sqrt(2.0));
    EXPECT_NEAR(corner.volume, 1.0 - 0.125, 1e-12);
    EXPECT_NEAR(hullVolume(corner.polytope), corner.volume, 1e-12);
    const ClippedPolytope slab = clipConvexPolytope(box, Eigen::Vector3d::UnitX(), 0.25);
    EXPECT_NEAR(slab.volume, 0.75, 1e-12);
    EXPECT_NEAR(extentAlong(slab.polytope, Eigen::Vector3d::UnitX())[1], 0.25, 1e-12);
    // A plane past the box keeps it whole; one before it leaves nothing.
    EXPECT_NEAR(clipConvexPolytope(box, Eigen::Vector3d::UnitX(), 2.0).volume, 1.0, 1e-12);
    const ClippedPolytope none = clipConvexPolytope(box, Eigen::Vector3d::UnitX(), -2.0);
    EXPECT_TRUE(none.polytope.points.empty());
    EXPECT_EQ(none.volume, 0.0);
    // With a margin the surface, not the points, stops at the plane.
    box.margin = 0.1;
    EXPECT_NEAR(extentAlong(clipConvexPolytope(box, Eigen::Vector3d::UnitX(), 0.25).polytope,
                            Eigen::Vector3d::UnitX())[1],
                0.25, 1e-12);
}

}  // namespace
}  // namespace btfracture
