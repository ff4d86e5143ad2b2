// SPDX-License-Identifier: Zlib
// Crack cuts, segmentation into fragments, volume classes (§5.2) and incomplete cracks (§5.3).
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/geometry/LevelSetBody.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace btfracture {
namespace {

// A 10 x 6 x 5 cm box at 64 voxels along its longest side (coarse: these tests only need the
// cut geometry, and they stay fast).
const Eigen::Vector3d kBoxSize(0.10, 0.06, 0.05);
const double kVoxel = 0.10 / 64;

LevelSetBody makeBox() {
    return LevelSetBody(test::box(Eigen::Vector3d::Zero(), kBoxSize, "box"), kVoxel);
}

// Cuts a corner cube of edge a [m] off a body whose corner is at `corner` (coordinates 0 or the
// side): three squares that meet along its edges, with crack id `id`.
void cutCorner(LevelSetBody& body, double a, const Eigen::Vector3d& corner, int id) {
    const double margin = 0.02;
    for (int axis = 0; axis < 3; ++axis) {
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;
        Eigen::Vector3d centre = corner, u = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
        const double sign = corner[axis] == 0.0 ? 1.0 : -1.0;
        centre[axis] = corner[axis] + sign * a;
        centre[i] = corner[i] + (corner[i] == 0.0 ? 1.0 : -1.0) * 0.5 * (a - margin);
        centre[j] = corner[j] + (corner[j] == 0.0 ? 1.0 : -1.0) * 0.5 * (a - margin);
        u[i] = 0.5 * (a + margin);
        v[j] = 0.5 * (a + margin);
        body.cutAlongSurface(test::sheet(centre, u, v, "corner face"), id);
    }
}

void expectClosedManifold(const TriangleMesh& mesh) {
    const MeshDefects d = inspectMesh(mesh);
    EXPECT_TRUE(d.isClosedManifold()) << mesh.name << ": " << d.describe();
    EXPECT_GT(d.signedVolume, 0.0) << mesh.name;
}

TEST(Fragments, UncutBodyIsOneFragmentKeepingItsSolver) {
    const LevelSetBody box = makeBox();
    EXPECT_TRUE(box.fragments(FragmentSettings(), test::kCollisionTriangles, 2).empty());
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_NEAR(pieces[0].mass.volume / box.massProperties().volume, 1.0, 1e-6);
    EXPECT_EQ(pieces[0].volumeClass, FragmentClass::KeepsParentSolver);
    EXPECT_TRUE(pieces[0].incompleteCracks.empty());
    ASSERT_TRUE(pieces[0].levelSet);
}

// A planar cut through a box gives exactly 2 fragments whose volumes add up
// to the original within the voxel tolerance and match the analytic split within 1 %.
TEST(Fragments, ObliquePlanarCutSplitsBoxIntoTwoAnalyticPieces) {
    LevelSetBody box = makeBox();
    const double volume = kBoxSize.prod();
    EXPECT_NEAR(box.massProperties().volume / volume, 1.0, 0.002);
    // Plane through c with normal n crosses only the four x-parallel edges, so the piece below
    // x_cut(y, z) has volume A_yz * x_cut(centre of the yz face).
    const Eigen::Vector3d c(0.0312, 0.03, 0.025), n = Eigen::Vector3d(1.0, 0.25, -0.15).normalized();
    const Eigen::Vector3d u = n.cross(Eigen::Vector3d::UnitZ()).normalized(), v = n.cross(u);
    box.cutAlongSurface(test::sheet(c, 0.1 * u, 0.1 * v, "oblique cut"), 7);
    const double left = kBoxSize.y() * kBoxSize.z() * c.x();  // plane passes through the face centre line
    const double right = volume - left;

    EXPECT_EQ(box.crackIds(), std::vector<int>{7});
    EXPECT_EQ(box.crackAt(c), 7);
    EXPECT_TRUE(box.isInsideCrack(c));
    EXPECT_FALSE(box.isInsideObject(c));
    EXPECT_TRUE(box.isInsideObject(c - 3 * kVoxel * n));
    EXPECT_EQ(box.crackAt(c - 3 * kVoxel * n), -1);

    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 2u);
    const double sum = pieces[0].mass.volume + pieces[1].mass.volume;
    std::printf(
        "oblique cut: pieces %.6g + %.6g = %.6g m^3 (uncut level set %.6g, box %.6g); analytic %.6g / %.6g\n",
        pieces[0].mass.volume, pieces[1].mass.volume, sum, box.massProperties().volume, volume, right, left);
    std::printf("  errors: sum %.4f %%, larger %.4f %%, smaller %.4f %%\n",
                100 * (sum / box.massProperties().volume - 1), 100 * (pieces[0].mass.volume / right - 1),
                100 * (pieces[1].mass.volume / left - 1));
    // Voxel tolerance of the sum: a tenth of a voxel layer over the cut. The slab is split
    // between the sides, so only the voxel error along the crack's rim remains.
    const double cutArea = kBoxSize.y() * kBoxSize.z() / std::abs(n.x());
    std::printf("  sum - uncut = %.3f voxel layers over the cut\n",
                (sum - box.massProperties().volume) / (kVoxel * cutArea));
    EXPECT_LT(std::abs(sum - box.massProperties().volume), 0.1 * kVoxel * cutArea);
    EXPECT_NEAR(sum / volume, 1.0, 0.002);  // the uncut box itself reads 0.13 % high (its edges)
    EXPECT_NEAR(pieces[0].mass.volume / right, 1.0, 0.01);
    EXPECT_NEAR(pieces[1].mass.volume / left, 1.0, 0.01);

    for (const Fragment& f : pieces) {
        EXPECT_TRUE(f.incompleteCracks.empty()) << f.name;
        EXPECT_EQ(f.volumeClass, FragmentClass::Breakable) << f.name;
        expectClosedManifold(f.collisionMesh);
        expectClosedManifold(f.visualMesh);
        expectClosedManifold(f.surfaceMesh);
        expectClosedManifold(f.convexHull);
        EXPECT_LE(static_cast<int>(f.collisionMesh.triangles.size()), test::kCollisionTriangles);
        ASSERT_TRUE(f.levelSet);
        EXPECT_TRUE(f.levelSet->crackIds().empty());
        EXPECT_NEAR(f.levelSet->massProperties().volume, f.mass.volume, 1e-12);
        EXPECT_DOUBLE_EQ(f.levelSet->originalVolume(), box.originalVolume());
        // The surface mesh encloses the fragment's level-set volume (its edges are chamfered by
        // about a voxel at this coarse resolution).
        EXPECT_NEAR(inspectMesh(f.surfaceMesh).signedVolume / f.mass.volume, 1.0, 0.03) << f.name;
    }
    // Centres of mass on the correct sides of the plane, and the pieces balance about the box centre.
    EXPECT_GT((pieces[0].mass.centreOfMass - c).dot(n), 0.0);
    EXPECT_LT((pieces[1].mass.centreOfMass - c).dot(n), 0.0);
    const Eigen::Vector3d combined = (pieces[0].mass.volume * pieces[0].mass.centreOfMass +
                                      pieces[1].mass.volume * pieces[1].mass.centreOfMass) /
                                     sum;
    EXPECT_LT((combined - 0.5 * kBoxSize).norm(), 0.5 * kVoxel);
}

TEST(Fragments, AxisAlignedCutMatchesAnalyticSplitAndCentres) {
    LevelSetBody box = makeBox();
    const double x = 0.0407;
    box.cutAlongSurface(test::sheet({x, 0.03, 0.025}, {0, 0.05, 0}, {0, 0, 0.05}), 0);
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 2u);
    const double area = kBoxSize.y() * kBoxSize.z();
    EXPECT_NEAR(pieces[0].mass.volume / (area * (kBoxSize.x() - x)), 1.0, 0.01);
    EXPECT_NEAR(pieces[1].mass.volume / (area * x), 1.0, 0.01);
    EXPECT_NEAR(pieces[0].mass.centreOfMass.x(), 0.5 * (x + kBoxSize.x()), 0.5 * kVoxel);
    EXPECT_NEAR(pieces[1].mass.centreOfMass.x(), 0.5 * x, 0.5 * kVoxel);
}

// Chips a few voxels across keep their mass (the pieces sum to the body) and get a hull that
// holds their volume and their centre of mass - where a chip's zero isosurface encloses next to
// nothing, the hull of its voxels - instead of being dropped (in the refracture chain such chips
// were 3.2 % of an event).
TEST(Fragments, ChipsAFewVoxelsAcrossKeepTheirVolumeAndGetAHull) {
    const double side = 0.1, voxel = side / 64;
    int voxelHulls = 0;
    setLogLevel(LogLevel::Debug);
    setLogSink([&](LogLevel, const std::string& m) {
        voxelHulls += m.find("hull of its voxels") != std::string::npos;
    });
    for (const double voxels : {2.0, 2.5, 3.0, 3.5}) {
        LevelSetBody cube(test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side), "cube"), voxel);
        cutCorner(cube, voxels * voxel, Eigen::Vector3d::Zero(), 1);
        const auto pieces = cube.fragments(FragmentSettings(), test::kCollisionTriangles);
        double sum = 0.0;
        for (const Fragment& f : pieces) {
            sum += f.mass.volume;
            EXPECT_TRUE(holdsVolume(f.convexHull, f.mass.volume, f.mass.centreOfMass))
                << voxels << " voxels: " << f.name << " of " << f.mass.volume << " m^3, hull of "
                << enclosedVolume(f.convexHull, f.mass.centreOfMass) << " m^3";
            // A body whose centre of mass lies outside its collision shape turns about a point
            // off its surface (a one-voxel chip's centre was 3.5 voxels from its hull and it sank).
            EXPECT_GT(windingNumber(f.convexHull.vertices, f.convexHull.triangles, f.mass.centreOfMass), 0.5)
                << voxels << " voxels: " << f.name << "'s centre of mass is outside its hull";
            EXPECT_GT(windingNumber(f.collisionMesh.vertices, f.collisionMesh.triangles, f.mass.centreOfMass),
                      0.5)
                << voxels << " voxels: " << f.name << "'s centre of mass is outside its collision mesh";
        }
        std::printf("corner chip of %.1f voxels: %zu pieces, volumes sum to %.4f of the cube\n", voxels,
                    pieces.size(), sum / (side * side * side));
        EXPECT_NEAR(sum / (side * side * side), 1.0, 0.01) << voxels << " voxels";
    }
    setLogSink(nullptr);
    setLogLevel(LogLevel::Info);
    std::printf("%d chips got the hull of their voxels\n", voxelHulls);
    EXPECT_GT(voxelHulls, 0);  // the case this test is for happened
}

// Two cracks crossing each other: four pieces, each near its analytic volume (voxels near the
// crossing line see only their nearest crack).
TEST(Fragments, CrossingCracksGiveFourAnalyticPieces) {
    LevelSetBody box = makeBox();
    const double x = 0.0437, y = 0.0252;
    box.cutAlongSurface(test::sheet({x, 0.03, 0.025}, {0, 0.05, 0}, {0, 0, 0.05}, "x crack"), 1);
    box.cutAlongSurface(test::sheet({0.05, y, 0.025}, {0.07, 0, 0}, {0, 0, 0.05}, "y crack"), 2);
    EXPECT_EQ(box.fragments(FragmentSettings(), test::kCollisionTriangles, 5).size(), 0u);
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 4u);
    const double z = kBoxSize.z();
    std::vector<double> expected = {(kBoxSize.x() - x) * (kBoxSize.y() - y) * z, x * (kBoxSize.y() - y) * z,
                                    (kBoxSize.x() - x) * y * z, x * y * z};
    std::sort(expected.rbegin(), expected.rend());
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) {
        std::printf("piece %d: %+.3f %% (%+.1f voxels)\n", k, 100 * (pieces[k].mass.volume / expected[k] - 1),
                    (pieces[k].mass.volume - expected[k]) / std::pow(kVoxel, 3));
        EXPECT_NEAR(pieces[k].mass.volume / expected[k], 1.0, 0.01) << k;
        EXPECT_TRUE(pieces[k].incompleteCracks.empty()) << k;
        sum += pieces[k].mass.volume;
    }
    EXPECT_NEAR(sum / box.massProperties().volume, 1.0, 0.005);
}

// A cut stopped halfway leaves one fragment, which carries the incomplete
// crack (§5.3); finishing the crack in that fragment's own body splits it.
TEST(Fragments, CutStoppedHalfwayLeavesOneFragmentWithAnIncompleteCrack) {
    LevelSetBody box = makeBox();
    const double x = 0.05;
    // Sheet covers y in [-0.01, 0.03]: half of the 6 cm section.
    box.cutAlongSurface(test::sheet({x, 0.01, 0.025}, {0, 0.02, 0}, {0, 0, 0.04}, "half crack"), 3);
    // Nothing came apart: with two pieces asked for, none is built (the engine's call).
    EXPECT_TRUE(box.fragments(FragmentSettings(), test::kCollisionTriangles, 2).empty());
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 1u);
    const Fragment& f = pieces[0];
    EXPECT_EQ(f.incompleteCracks, std::vector<int>{3});
    EXPECT_NEAR(f.mass.volume / box.massProperties().volume, 1.0, 1e-3);
    EXPECT_EQ(f.volumeClass, FragmentClass::KeepsParentSolver);
    expectClosedManifold(f.surfaceMesh);
    expectClosedManifold(f.collisionMesh);
    // The BEM surface excludes the incomplete crack; the visual mesh shows it as a slit.
    EXPECT_NEAR(inspectMesh(f.surfaceMesh).signedVolume / f.mass.volume, 1.0, 0.02);
    EXPECT_LT(inspectMesh(f.visualMesh).signedVolume, inspectMesh(f.surfaceMesh).signedVolume);

    ASSERT_TRUE(f.levelSet);
    LevelSetBody& child = *f.levelSet;
    EXPECT_EQ(child.crackIds(), std::vector<int>{3});
    EXPECT_EQ(child.crackAt({x, 0.01, 0.025}), 3);
    EXPECT_FALSE(child.isInsideObject({x, 0.01, 0.025}));
    EXPECT_TRUE(child.isInsideObject({x, 0.05, 0.025}));
    // The fragment's crack mesh numbers its carried sheets from 0: the level set takes those ids.
    EXPECT_THROW(child.renameCracks({{4, 0}}), Error);
    child.renameCracks({{3, 0}});
    EXPECT_EQ(child.crackIds(), std::vector<int>{0});
    EXPECT_EQ(child.crackAt({x, 0.01, 0.025}), 0);
    // The crack grows through the rest of the section later (§5.3: old cracks keep growing).
    child.cutAlongSurface(test::sheet({x, 0.05, 0.025}, {0, 0.025, 0}, {0, 0, 0.04}, "rest of crack"), 0);
    const auto halves = child.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(halves.size(), 2u);
    for (const Fragment& h : halves) {
        EXPECT_TRUE(h.incompleteCracks.empty());
        EXPECT_NEAR(h.mass.volume / (0.5 * box.massProperties().volume), 1.0, 0.01);
        EXPECT_EQ(h.volumeClass, FragmentClass::Breakable);
    }
}

// Each voxel's material counts for one fragment only. Two parallel cuts 2.2 voxels apart leave a
// chip one voxel layer thick between their slabs; the side probes of the first sheet's crack
// voxels (2-5 voxels out) reach past the chip into the piece beyond, which used to claim the
// chip's voxels too: the pieces then summed to more than the box, and that piece's own level set
// (its body when it breaks again, §5.3) held the chip as a second piece. (In `make demo` such
// islands split off as up to 26 specks at a piece's next event.)
TEST(Fragments, AChipBetweenCloseCutsIsClaimedByNoOtherPiece) {
    LevelSetBody box = makeBox();
    const double x0 = 32.0 * kVoxel, x1 = 34.2 * kVoxel;
    box.cutAlongSurface(test::sheet({x0, 0.03, 0.025}, {0, 0.04, 0}, {0, 0, 0.035}, "first plane"), 1);
    box.cutAlongSurface(test::sheet({x1, 0.03, 0.025}, {0, 0.04, 0}, {0, 0, 0.035}, "second plane"), 2);
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    double sum = 0.0;
    for (const Fragment& f : pieces) sum += f.mass.volume;
    std::printf("%zu pieces, volumes sum to %+.3f %% of the box\n", pieces.size(),
                100.0 * (sum / box.massProperties().volume - 1.0));
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_NEAR(sum / box.massProperties().volume, 1.0, 0.005);
    for (const Fragment& f : pieces) {
        if (!f.levelSet) continue;
        const auto own = f.levelSet->fragments(FragmentSettings(), test::kCollisionTriangles);
        std::printf("%s: %.2f %% of the box, its own level set in %zu piece(s)\n", f.name.c_str(),
                    100.0 * f.fractionOfOriginal, own.size());
        EXPECT_EQ(own.size(), 1u) << f.name;
    }
}

// A star of cracks through the thickness, meeting at a line inside the box (window_pane's radial
// cracks): three reach the surface and cut the box into three pieces, two short ones end inside
// (incomplete). Around the meeting line, slab voxels that no crack voxel hands to a piece sit
// beside filled crack voxels; every piece's surfaces must still be closed, and hold its volume.
TEST(Fragments, CracksMeetingInsideLeaveClosedSurfaces) {
    LevelSetBody box = makeBox();
    const Eigen::Vector3d centre(0.047, 0.031, 0.025);
    constexpr int kRays = 5;
    for (int i = 0; i < kRays; ++i) {
        const double angle = 2.0 * M_PI * i / kRays;
        const Eigen::Vector3d d(std::cos(angle), std::sin(angle), 0.0);
        const double length = i % 2 == 0 ? 0.08 : 0.012;  // through the surface, or ending inside
        box.cutAlongSurface(test::sheet(centre + 0.5 * length * d, 0.5 * length * d, {0, 0, 0.03}, "ray"), i);
    }
    const auto pieces = box.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 3u);
    double sum = 0.0;
    for (const Fragment& f : pieces) {
        sum += f.mass.volume;
        expectClosedManifold(f.collisionMesh);
        expectClosedManifold(f.visualMesh);
        if (f.surfaceMesh.triangles.empty()) continue;
        expectClosedManifold(f.surfaceMesh);
        EXPECT_NEAR(inspectMesh(f.surfaceMesh).signedVolume / f.mass.volume, 1.0, 0.02) << f.name;
    }
    EXPECT_NEAR(sum / box.massProperties().volume, 1.0, 0.005);
}

// An open mesh's enclosed volume depends on the point it is taken about: holdsVolume takes it
// about the centre of mass. A box without its top face, 100 m up: about its centre it encloses
// 5/6 of the box (the missing face held (1/3) b A_top = V/6), about the origin far less than nothing.
TEST(Fragments, HoldsVolumeIsMeasuredAboutTheCentreOfMass) {
    const Eigen::Vector3d half(0.05, 0.03, 0.025), up(0.0, 100.0, 0.0);
    TriangleMesh open = btfracture::makeBox(half);
    for (auto& v : open.vertices) v += up;
    const double volume = 8.0 * half.prod();
    EXPECT_TRUE(holdsVolume(open, volume, up));
    const auto onTop = [&](const auto& t) {
        return std::all_of(t.begin(), t.end(),
                           [&](int i) { return open.vertices[i].y() > up.y() + 0.5 * half.y(); });
    };
    open.triangles.erase(std::remove_if(open.triangles.begin(), open.triangles.end(), onTop),
                         open.triangles.end());
    ASSERT_EQ(open.triangles.size(), 10u);
    EXPECT_NEAR(enclosedVolume(open, up), 5.0 / 6.0 * volume, 1e-9 * volume);
    EXPECT_LT(enclosedVolume(open), 0.0);
    EXPECT_TRUE(holdsVolume(open, volume, up));
    EXPECT_FALSE(holdsVolume(open, 10.0 * volume, up));  // 1/12 of that volume
}

// Three corner cuts and a plane give pieces in every class of §5.2.
TEST(Fragments, VolumeClassesOnConstructedCase) {
    const double side = 0.1;
    LevelSetBody cube(test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side), "cube"), side / 64);
    const double a = 0.15 * side, b = 0.25 * side, x = 0.7 * side;
    cutCorner(cube, a, Eigen::Vector3d::Zero(), 1);
    cutCorner(cube, b, Eigen::Vector3d::Constant(side), 2);
    cube.cutAlongSurface(test::sheet({x, 0.5 * side, 0.5 * side}, {0, 0.6 * side, 0}, {0, 0, 0.6 * side}), 3);
    const auto pieces = cube.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(pieces.size(), 4u);
    const double v = side * side * side;
    const double expected[4] = {x * side * side - a * a * a, (side - x) * side * side - b * b * b, b * b * b,
                                a * a * a};
    const FragmentClass classes[4] = {FragmentClass::Breakable, FragmentClass::Breakable,
                                      FragmentClass::Unbreakable, FragmentClass::ConvexHull};
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) {
        std::printf("piece %d: %.5f %% of original (analytic %.5f %%), %s\n", k,
                    100 * pieces[k].fractionOfOriginal, 100 * expected[k] / v,
                    fragmentClassName(pieces[k].volumeClass));
        EXPECT_EQ(pieces[k].volumeClass, classes[k]) << k;
        // Small pieces are 10-16 voxels wide here: their edges cost about a percent.
        EXPECT_NEAR(pieces[k].mass.volume / expected[k], 1.0, k < 2 ? 0.01 : 0.03) << k;
        EXPECT_EQ(static_cast<bool>(pieces[k].levelSet), k < 2) << k;
        EXPECT_EQ(pieces[k].surfaceMesh.triangles.empty(), k >= 2) << k;
        expectClosedManifold(pieces[k].collisionMesh);
        expectClosedManifold(pieces[k].convexHull);
        sum += pieces[k].mass.volume;
    }
    const double crackArea = 3 * a * a + 3 * b * b + side * side;
    EXPECT_LT(std::abs(sum - cube.massProperties().volume), 0.1 * (side / 64) * crackArea);

    // Cutting only the small corner leaves the rest with > 95 % of its parent: it keeps the solver.
    LevelSetBody cube2(test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side), "cube"),
                       side / 64);
    cutCorner(cube2, a, Eigen::Vector3d::Zero(), 1);
    const auto two = cube2.fragments(FragmentSettings(), test::kCollisionTriangles);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].volumeClass, FragmentClass::KeepsParentSolver);
    EXPECT_EQ(two[1].volumeClass, FragmentClass::ConvexHull);
}

TEST(Fragments, ClassifyFragmentThresholdsAreSettings) {
    FragmentSettings s;
    EXPECT_EQ(classifyFragment(0.005, 1.0, 1.0, s), FragmentClass::ConvexHull);
    EXPECT_EQ(classifyFragment(0.0051, 1.0, 1.0, s), FragmentClass::Unbreakable);
    EXPECT_EQ(classifyFragment(0.02, 1.0, 1.0, s), FragmentClass::Unbreakable);
    EXPECT_EQ(classifyFragment(0.03, 1.0, 1.0, s), FragmentClass::Breakable);
    EXPECT_EQ(classifyFragment(0.9, 0.95, 1.0, s), FragmentClass::Breakable);
    EXPECT_EQ(classifyFragment(0.91, 0.95, 1.0, s), FragmentClass::KeepsParentSolver);
    // (d) needs a breakable-sized fragment: a small parent's near-whole piece stays small.
    EXPECT_EQ(classifyFragment(0.0149, 0.015, 1.0, s), FragmentClass::Unbreakable);
    s.convexHullMaxFraction = 0.01;
    EXPECT_EQ(classifyFragment(0.008, 1.0, 1.0, s), FragmentClass::ConvexHull);
    s.unbreakableMaxFraction = 0.005;
    EXPECT_THROW(s.validate(), Error);
    EXPECT_THROW(classifyFragment(0.0, 1.0, 1.0, FragmentSettings()), Error);
    EXPECT_THROW(makeBox().fragments(FragmentSettings(), 2), Error);  // collision meshes of 2 triangles
}

// Same input, same output: bit for bit, whether OpenVDB and the integrals run on one thread or many.
TEST(Fragments, SegmentationIsDeterministicAndThreadCountIndependent) {
    auto run = [] {
        LevelSetBody box = makeBox();
        box.cutAlongSurface(test::sheet({0.06, 0.03, 0.025}, {0.01, 0.05, 0}, {0, 0.01, 0.05}), 0);
        return box.fragments(FragmentSettings(), test::kCollisionTriangles);
    };
    std::vector<Fragment> serial;
    {
        tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
        serial = run();
    }
    for (const auto& parallel : {run(), run()}) {
        ASSERT_EQ(serial.size(), parallel.size());
        for (size_t k = 0; k < serial.size(); ++k) {
            EXPECT_EQ(serial[k].mass.volume, parallel[k].mass.volume);
            EXPECT_EQ(serial[k].mass.centreOfMass, parallel[k].mass.centreOfMass);
            EXPECT_EQ(serial[k].mass.inertiaPerDensity, parallel[k].mass.inertiaPerDensity);
            EXPECT_EQ(serial[k].collisionMesh.vertices, parallel[k].collisionMesh.vertices);
            EXPECT_EQ(serial[k].visualMesh.triangles, parallel[k].visualMesh.triangles);
        }
    }
}

TEST(Fragments, BadCrackSheetsAreRejectedAndMissesChangeNothing) {
    LevelSetBody box = makeBox();
    TriangleMesh sheet = test::sheet({0.05, 0.03, 0.025}, {0, 0.05, 0}, {0, 0, 0.05});
    EXPECT_THROW(box.cutAlongSurface(sheet, -1), Error);
    EXPECT_THROW(box.cutAlongSurface(TriangleMesh{}, 0), Error);
    TriangleMesh badIndex = sheet;
    badIndex.triangles[0][2] = 9;
    EXPECT_THROW(box.cutAlongSurface(badIndex, 0), Error);
    TriangleMesh nan = sheet;
    nan.vertices[1].x() = NAN;
    EXPECT_THROW(box.cutAlongSurface(nan, 0), Error);
    box.cutAlongSurface(test::sheet({0.5, 0.5, 0.5}, {0, 0.05, 0}, {0, 0, 0.05}), 0);  // far away
    EXPECT_TRUE(box.crackIds().empty());
    EXPECT_EQ(box.fragments(FragmentSettings(), test::kCollisionTriangles).size(), 1u);
}

}  // namespace
}  // namespace btfracture
