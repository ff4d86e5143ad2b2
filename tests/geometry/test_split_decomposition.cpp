// SPDX-License-Identifier: Zlib
// Convex decomposition by plane splits (geometry/SplitDecomposition.h): the pieces cover the
// solid, their summed hull volume approaches the solid's as the piece budget grows, a convex
// mesh stays one piece, bad input is named.
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/Timer.h>
#include <btFracture/geometry/ConvexHull.h>
#include <btFracture/geometry/SplitDecomposition.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <random>

namespace btfracture {
namespace {

// Largest distance [m] by which a point lies outside every piece's hull (0 when each point is in
// one of them).
double uncovered(const SplitDecomposition& d, const std::vector<Eigen::Vector3d>& points) {
    std::vector<TriangleMesh> hulls;
    for (const auto& piece : d.pieces) hulls.push_back(convexHullMesh(piece, "piece"));
    double worst = 0.0;
    for (const auto& p : points) {
        double best = 1e300;
        for (const TriangleMesh& hull : hulls) {
            double outside = 0.0;
            double largest = 0.0;
            for (const auto& t : hull.triangles) {
                const Eigen::Vector3d& a = hull.vertices[t[0]];
                largest = std::max(largest, (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).norm());
            }
            for (const auto& t : hull.triangles) {
                const Eigen::Vector3d& a = hull.vertices[t[0]];
                const Eigen::Vector3d n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a);
                // A sliver's normal is rounding noise; the face it lies on has larger triangles.
                if (n.norm() < 1e-6 * largest) continue;
                outside = std::max(outside, (p - a).dot(n.normalized()));
            }
            best = std::min(best, outside);
        }
        worst = std::max(worst, best);
    }
    return worst;
}

SplitDecomposition timed(const TriangleMesh& mesh, const SplitDecompositionOptions& options,
                         const char* what) {
    const Timer timer;
    SplitDecomposition d = splitDecomposition(mesh, options);
    const double ms = 1e3 * timer.seconds();
    std::printf("%s, %zu triangles, budget %d: %zu pieces, hull / mesh volume %.4f, %.1f ms\n", what,
                mesh.triangles.size(), options.maxPieces, d.pieces.size(), d.hullVolume / d.meshVolume, ms);
    return d;
}

TEST(SplitDecomposition, ConvexMeshStaysOnePiece) {
    const SplitDecomposition d = splitDecomposition(test::sphere(0.05, 3));
    ASSERT_EQ(d.pieces.size(), 1u);
    EXPECT_NEAR(d.hullVolume, d.meshVolume, 1e-12);
}

// A torus (ring) has a hole its hull fills: the summed hull volume falls towards the ring's own
// volume as the budget grows, and the pieces always cover the ring's surface.
TEST(SplitDecomposition, TorusHullVolumeConvergesAndCovers) {
    TriangleMesh ring = makeTorus(0.1, 0.03, 48, 16);
    ring.name = "ring";
    double previous = 1e300;
    for (const int budget : {4, 8, 16, 32}) {
        SplitDecompositionOptions options;
        options.maxPieces = budget;
        options.concavity = 0.0;
        const SplitDecomposition d = timed(ring, options, "torus");
        EXPECT_EQ(static_cast<int>(d.pieces.size()), budget);
        const double ratio = d.hullVolume / d.meshVolume;
        EXPECT_LT(ratio, previous);
        previous = ratio;
        EXPECT_LT(uncovered(d, ring.vertices), 1e-12);
    }
    EXPECT_LT(previous, 1.1);  // 32 pieces
}

// Candidate cuts of a torus tie (every first cut leaves the same summed hull volume), so the last
// bits of the hull volumes must not choose: the torus moved off the origin, where every
// coordinate rounds differently, gets the same pieces.
TEST(SplitDecomposition, RoundingDoesNotChooseTheCut) {
    TriangleMesh ring = makeTorus(0.1, 0.03, 48, 16);
    ring.name = "ring";
    TriangleMesh moved = ring;
    const Eigen::Vector3d offset(0.3711, -1.237, 2.0519);
    for (auto& v : moved.vertices) v += offset;
    for (const int budget : {4, 8, 16}) {
        SplitDecompositionOptions options;
        options.maxPieces = budget;
        options.concavity = 0.0;
        const SplitDecomposition a = splitDecomposition(ring, options);
        const SplitDecomposition b = splitDecomposition(moved, options);
        ASSERT_EQ(a.pieces.size(), b.pieces.size());
        EXPECT_NEAR(b.hullVolume / b.meshVolume, a.hullVolume / a.meshVolume, 1e-6) << budget << " pieces";
        for (std::size_t k = 0; k < a.pieces.size(); ++k) {
            Eigen::AlignedBox3d boxA, boxB;
            for (const auto& p : a.pieces[k]) boxA.extend(p);
            for (const auto& p : b.pieces[k]) boxB.extend(p);
            EXPECT_LT((boxB.min() - offset - boxA.min()).norm(), 1e-9) << budget << " pieces, piece " << k;
            EXPECT_LT((boxB.max() - offset - boxA.max()).norm(), 1e-9) << budget << " pieces, piece " << k;
            EXPECT_NEAR(convexHullVolume(b.pieces[k], "b"), convexHullVolume(a.pieces[k], "a"),
                        1e-9 * a.meshVolume);
        }
    }
}

// The bunny's pieces hold every point inside it (the inner corners of their boxes included), and
// their hulls add at most 10 % to its volume.
TEST(SplitDecomposition, BunnyPiecesHoldItsSolid) {
    const TriangleMesh bunny = test::demoMesh("bunny.obj", 0.15);
    SplitDecompositionOptions options;
    options.concavity = 0.0;
    const SplitDecomposition d = timed(bunny, options, "bunny");
    EXPECT_EQ(d.pieces.size(), 16u);
    EXPECT_GT(d.hullVolume, d.meshVolume);
    EXPECT_LT(d.hullVolume / d.meshVolume, 1.1);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.075, 0.075);
    std::vector<Eigen::Vector3d> inside;
    for (int i = 0; i < 1000; ++i) {
        const Eigen::Vector3d p(u(rng), u(rng), u(rng));
        if (windingNumber(bunny.vertices, bunny.triangles, p) > 0.5) inside.push_back(p);
    }
    EXPECT_GT(inside.size(), 100u);
    EXPECT_LT(uncovered(d, inside), 1e-12);
    EXPECT_LT(uncovered(d, bunny.vertices), 1e-12);
}

TEST(SplitDecomposition, BadInputIsNamed) {
    TriangleMesh flat = test::sheet({0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, "flat sheet");
    try {
        splitDecomposition(flat);
        FAIL() << "a flat sheet was decomposed";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("flat sheet"), std::string::npos) << e.what();
    }
    SplitDecompositionOptions options;
    options.maxPieces = 0;
    EXPECT_THROW(splitDecomposition(test::sphere(0.05, 2), options), Error);
}

}  // namespace
}  // namespace btfracture
