// SPDX-License-Identifier: Zlib
// BEM sources of curved fragments (§5.3): a bunny cut by a bent crack sheet and an
// incomplete crack; each breakable piece's LevelSetBody::bemSourceMesh must be a closed,
// manifold, intersection-free surface of the piece's volume that remeshForBem turns into a
// valid BEM mesh near the target count.
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Timer.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/geometry/MeshDebris.h>
#include <btFracture/geometry/Remesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace btfracture {
namespace {

// Two rectangles meeting at a 40 degree bend along the z axis through `centre`: a crack sheet
// that is not a plane, so its rim on the curved surface is not a planar curve either.
TriangleMesh bentSheet(const Eigen::Vector3d& centre, double half) {
    TriangleMesh m;
    m.name = "bent crack";
    const Eigen::Vector3d left(-std::cos(0.35), std::sin(0.35), 0.0),
        right(std::cos(0.35), std::sin(0.35), 0.0);
    const Eigen::Vector3d z(0, 0, half);
    m.vertices = {centre - z,
                  centre + z,
                  centre + 2 * half * left - z,
                  centre + 2 * half * left + z,
                  centre + 2 * half * right - z,
                  centre + 2 * half * right + z};
    m.triangles = {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}};
    return m;
}

TEST(BemSource, CurvedFragmentsGetClosedIntersectionFreeBemMeshes) {
    const double size = 0.15;
    LevelSetBody bunny(test::demoMesh("bunny.obj", size), size / 96);
    bunny.cutAlongSurface(bentSheet(Eigen::Vector3d(0.005, -0.01, 0.0), 0.2), 1);
    // A small crack inside the upper piece: it ends in the material, so it is incomplete there
    // (filled in the BEM source, carried as a crack).
    bunny.cutAlongSurface(test::sheet({-0.01, 0.025, 0.0}, {0, 0.008, 0}, {0, 0, 0.012}, "incomplete crack"),
                          2);
    const std::vector<Fragment> pieces = bunny.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_GE(pieces.size(), 2u);
    const int target = 500;
    int checked = 0;
    for (const Fragment& f : pieces) {
        if (f.volumeClass != FragmentClass::Breakable && f.volumeClass != FragmentClass::KeepsParentSolver)
            continue;
        ASSERT_TRUE(f.levelSet) << f.name;
        Timer timer;
        const TriangleMesh source = f.levelSet->bemSourceMesh(target, 3.0);
        const double sourceSeconds = timer.seconds();
        const MeshDefects d = inspectMesh(source);
        EXPECT_TRUE(d.isClosedSolid()) << f.name << ": " << d.describe();
        EXPECT_NEAR(d.signedVolume / f.mass.volume, 1.0, 0.03) << f.name;
        timer.restart();
        RemeshOptions options;
        options.maxRefinements = 1;  // as BemFractureEngine
        const TriangleMesh bem = remeshForBem(source, target, options);
        const MeshDefects b = inspectMesh(bem);
        std::printf(
            "%s: %.1f %% of the bunny, %zu incomplete cracks; collision mesh %d intersecting pairs; "
            "source %zu triangles, volume %+.2f %%, %.3f s; BEM %zu triangles, %.3f s\n",
            f.name.c_str(), 100 * f.fractionOfOriginal, f.incompleteCracks.size(),
            inspectMesh(f.collisionMesh).intersectingPairs, source.triangles.size(),
            100 * (d.signedVolume / f.mass.volume - 1), sourceSeconds, bem.triangles.size(), timer.seconds());
        EXPECT_TRUE(b.isClosedSolid()) << f.name << " BEM: " << b.describe();
        EXPECT_GT(b.signedVolume, 0.0);
        EXPECT_NEAR(static_cast<double>(bem.triangles.size()) / target, 1.0, 0.1) << f.name;
        EXPECT_NEAR(b.signedVolume / f.mass.volume, 1.0, 0.05) << f.name;
        ++checked;
    }
    EXPECT_GE(checked, 2);
    EXPECT_TRUE(std::any_of(pieces.begin(), pieces.end(),
                            [](const Fragment& f) { return !f.incompleteCracks.empty(); }));
}

// A coarse level set leaves islands and small voids beside a fragment's surface; a BEM source
// keeps only the pieces of at least 1 % of the largest one's volume. Here: a 1 m box, a 5 cm box
// outside it and a 5 cm cavity inside it (inward-facing) are reduced to the 1 m box; two equal
// boxes are both kept (the BEM then rejects the mesh with its own error).
TEST(BemSource, DebrisPiecesAreDropped) {
    auto append = [](TriangleMesh& to, const TriangleMesh& from, bool inward) {
        const int base = static_cast<int>(to.vertices.size());
        to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
        for (auto t : from.triangles) {
            if (inward) std::swap(t[1], t[2]);
            to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        }
    };
    TriangleMesh mesh;
    append(mesh, test::box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)), false);
    append(mesh, test::box(Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2.05, 0.05, 0.05)), false);
    append(mesh, test::box(Eigen::Vector3d(0.4, 0.4, 0.4), Eigen::Vector3d(0.45, 0.45, 0.45)), true);
    const DroppedDebris dropped = dropDebris(mesh, 0.01);
    EXPECT_EQ(dropped.pieces, 2);
    EXPECT_NEAR(dropped.volume, 2 * 1.25e-4, 1e-9);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(inspectMesh(mesh).components, 1);
    EXPECT_NEAR(enclosedVolume(mesh), 1.0, 1e-12);

    TriangleMesh twins;
    append(twins, test::box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)), false);
    append(twins, test::box(Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(3, 1, 1)), false);
    EXPECT_EQ(dropDebris(twins, 0.01).pieces, 0);
    EXPECT_EQ(twins.triangles.size(), 24u);
}

TEST(BemSource, BadArgumentsNameTheBody) {
    const LevelSetBody box(test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.1), "cube"),
                           0.1 / 32);
    EXPECT_THROW(box.bemSourceMesh(3, 3.0), Error);
    EXPECT_THROW(box.bemSourceMesh(500, 0.0), Error);
    try {
        box.bemSourceMesh(500, std::nan(""));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cube"), std::string::npos) << e.what();
    }
    // Coarser than the body's voxels: a closed surface of the box's volume.
    const MeshDefects d = inspectMesh(box.bemSourceMesh(200, 3.0));
    EXPECT_TRUE(d.isClosedSolid()) << d.describe();
    EXPECT_NEAR(d.signedVolume / 1e-3, 1.0, 0.05);
}

}  // namespace
}  // namespace btfracture
