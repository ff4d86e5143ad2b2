// SPDX-License-Identifier: Zlib
// LevelSetBody: mass properties against exact polyhedral integrals, queries and curvature.
#include "TestShapes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/geometry/LevelSetBody.h>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <cstdio>

namespace btfracture {
namespace {

struct MassErrors {
    double volume;        // relative
    double centreVoxels;  // distance in voxels
    double inertia;       // largest relative error of a principal moment, and of the tensor (Frobenius)
    double inertiaTensor;
};

MassErrors compare(const MassProperties& measured, const MassProperties& exact, double voxel) {
    MassErrors e;
    e.volume = std::abs(measured.volume - exact.volume) / exact.volume;
    e.centreVoxels = (measured.centreOfMass - exact.centreOfMass).norm() / voxel;
    const Eigen::Vector3d a =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(measured.inertiaPerDensity).eigenvalues();
    const Eigen::Vector3d b =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(exact.inertiaPerDensity).eigenvalues();
    e.inertia = ((a - b).array() / b.array()).abs().maxCoeff();
    e.inertiaTensor =
        (measured.inertiaPerDensity - exact.inertiaPerDensity).norm() / exact.inertiaPerDensity.norm();
    return e;
}

// Volume within 0.5 %, centre of mass within half a voxel, inertia within
// 1 % at the default voxel size (128 voxels across the longest side).
void expectLevelSetMatchesMesh(const std::string& file, double size) {
    const TriangleMesh mesh = test::demoMesh(file, size);
    const MassProperties exact = computeMassProperties(mesh);
    const double voxel = LevelSetBody::defaultVoxelSize(mesh);
    const LevelSetBody body(mesh, voxel);
    const MassErrors e = compare(body.massProperties(), exact, voxel);
    std::printf(
        "%s at %g m, voxel %g m: volume %+.4f %%, centre %.4f voxel, inertia %.4f %% (principal), %.4f %% "
        "(tensor)\n",
        file.c_str(), size, voxel, 100 * (body.massProperties().volume / exact.volume - 1), e.centreVoxels,
        100 * e.inertia, 100 * e.inertiaTensor);
    EXPECT_LT(e.volume, 0.005);
    EXPECT_LT(e.centreVoxels, 0.5);
    EXPECT_LT(e.inertia, 0.01);
    EXPECT_LT(e.inertiaTensor, 0.01);
    EXPECT_DOUBLE_EQ(body.originalVolume(), body.massProperties().volume);
}

TEST(LevelSetBody, BunnyMassPropertiesMatchMeshAtDefaultVoxelSize) {
    expectLevelSetMatchesMesh("bunny.obj", 0.15);
}

TEST(LevelSetBody, ArmadilloMassPropertiesMatchMeshAtDefaultVoxelSize) {
    expectLevelSetMatchesMesh("armadillo.obj", 0.3);
}

// A 6 mm pane 60 cm wide, turned off the grid's axes: 128 voxels across its longest side put 1.3
// through it (volume +1.4 %); the default puts 4 through its mean thickness 2V/A (+0.05 %), up
// to 1,024 across. A chunky body keeps 128 across.
TEST(LevelSetBody, DefaultVoxelResolvesAThinPlate) {
    TriangleMesh pane = makeBox(Eigen::Vector3d(0.3, 0.2, 0.003));
    pane.name = "pane";
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
    for (auto& v : pane.vertices) v = turn * v;  // off the grid's axes
    const double exact = computeMassProperties(pane).volume;
    const double voxel = LevelSetBody::defaultVoxelSize(pane);
    const double thickness = 2.0 * exact / surfaceArea(pane);
    EXPECT_NEAR(voxel, thickness / LevelSetBody::kDefaultVoxelsThrough, 1e-12);
    EXPECT_LT(voxel, 0.6 / LevelSetBody::kDefaultVoxelsAcross);
    const double volume = LevelSetBody(pane, voxel).massProperties().volume;
    const double coarse =
        LevelSetBody(pane, 0.6 / LevelSetBody::kDefaultVoxelsAcross).massProperties().volume;
    std::printf("pane: voxel %g m, volume %+.3f %% (at the longest side / 128: %+.3f %%)\n", voxel,
                100 * (volume / exact - 1), 100 * (coarse / exact - 1));
    EXPECT_LT(std::abs(volume / exact - 1), 0.005);
    // An inside-out mesh (LevelSetBody flips it with a warning) gets the same default.
    TriangleMesh flipped = pane;
    for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
    EXPECT_DOUBLE_EQ(LevelSetBody::defaultVoxelSize(flipped), voxel);

    // A 1 mm sheet 2 m long would need 8,000 voxels across: the default stops at 1,024.
    const TriangleMesh sheet = makeBox(Eigen::Vector3d(1.0, 0.5, 0.0005));
    EXPECT_DOUBLE_EQ(LevelSetBody::defaultVoxelSize(sheet), 2.0 / LevelSetBody::kDefaultMaxVoxelsAcross);

    const TriangleMesh cube = makeBox(Eigen::Vector3d(0.1, 0.1, 0.1));
    EXPECT_DOUBLE_EQ(LevelSetBody::defaultVoxelSize(cube), 0.2 / LevelSetBody::kDefaultVoxelsAcross);
}

TEST(LevelSetBody, OffsetSphereMassIsAnalytic) {
    // Coarse on purpose (40 voxels across): the plane-fraction integrals still hit a sphere closely.
    const double r = 0.05;
    const Eigen::Vector3d centre(0.3, -0.2, 0.1);
    const LevelSetBody body(test::sphere(r, 5, centre), 2 * r / 40);
    const MassProperties& m = body.massProperties();
    const double volume = 4.0 / 3.0 * M_PI * r * r * r;
    EXPECT_NEAR(m.volume / volume, 1.0, 0.005);
    EXPECT_LT((m.centreOfMass - centre).norm(), 0.05 * body.voxelSize());
    const double moment = 0.4 * volume * r * r;
    EXPECT_NEAR(m.inertiaPerDensity(0, 0) / moment, 1.0, 0.01);
    EXPECT_NEAR(m.inertiaPerDensity(1, 1) / moment, 1.0, 0.01);
    EXPECT_NEAR(m.inertiaPerDensity(2, 2) / moment, 1.0, 0.01);
    EXPECT_LT(std::abs(m.inertiaPerDensity(0, 1)) / moment, 1e-3);
}

TEST(LevelSetBody, InsideQueriesAndSignedDistance) {
    const LevelSetBody body(test::box({0, 0, 0}, {0.1, 0.1, 0.1}), 0.0025);
    EXPECT_TRUE(body.isInsideObject({0.05, 0.05, 0.05}));
    EXPECT_FALSE(body.isInsideObject({0.05, 0.05, 0.11}));
    EXPECT_FALSE(body.isInsideCrack({0.05, 0.05, 0.05}));
    EXPECT_EQ(body.crackAt({0.05, 0.05, 0.05}), -1);
    EXPECT_NEAR(body.signedDistance({0.05, 0.05, 0.095}), -0.005, 1e-4);
    EXPECT_NEAR(body.signedDistance({0.05, 0.05, 0.102}), 0.002, 1e-4);
    // Far outside: clamped to the narrow band (3 voxels).
    EXPECT_NEAR(body.signedDistance({1, 1, 1}), 3 * 0.0025, 1e-6);
    EXPECT_THROW(body.signedDistance({NAN, 0, 0}), Error);
}

TEST(LevelSetBody, MeanCurvatureOfSphereIsInverseRadius) {
    const double r = 0.05;
    const LevelSetBody body(test::sphere(r, 5), 2 * r / 64);
    for (const Eigen::Vector3d& dir :
         {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 1, 1).normalized(),
          Eigen::Vector3d(-0.3, 0.5, 0.8).normalized()}) {
        // Points slightly off the surface are projected onto it first.
        EXPECT_NEAR(body.meanCurvature(r * dir) * r, 1.0, 0.03);
        EXPECT_NEAR(body.meanCurvature((r + 0.5 * body.voxelSize()) * dir) * r, 1.0, 0.03);
    }
}

TEST(LevelSetBody, MeanCurvatureOfFlatFaceIsExactlyZeroAndEdgesAreConvex) {
    const LevelSetBody body(test::box({0, 0, 0}, {0.2, 0.1, 0.1}), 0.002);
    EXPECT_EQ(body.meanCurvature({0.1, 0.05, 0.1}), 0.0);
    EXPECT_EQ(body.meanCurvature({0.07, 0.0, 0.04}), 0.0);
    // Near an edge the resolved curvature is large and positive (convex).
    EXPECT_GT(body.meanCurvature({0.1, 0.0, 0.1}), 10.0);
    EXPECT_THROW(body.meanCurvature({0.1, 0.05, 0.05}), Error);  // centre: not near the surface
}

TEST(LevelSetBody, BadInputIsRejectedWithAMessage) {
    TriangleMesh open = test::box({0, 0, 0}, {1, 1, 1}, "open box");
    open.triangles.pop_back();
    EXPECT_THROW(LevelSetBody(open, 0.05), Error);
    const TriangleMesh cube = test::box({0, 0, 0}, {1, 1, 1});
    EXPECT_THROW(LevelSetBody(cube, 0.0), Error);
    EXPECT_THROW(LevelSetBody(cube, -1.0), Error);
    EXPECT_THROW(LevelSetBody(cube, NAN), Error);
    try {
        LevelSetBody(cube, 1e-4);
        FAIL() << "10^4 voxels across accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("voxels across"), std::string::npos) << e.what();
    }
}

TEST(LevelSetBody, VisualMeshIsClosedAndEnclosesTheVolume) {
    const TriangleMesh mesh = test::demoMesh("bunny.obj", 0.15);
    const LevelSetBody body(mesh, 0.15 / 64);
    const TriangleMesh visual = body.visualMesh();
    const MeshDefects d = inspectMesh(visual);
    EXPECT_TRUE(d.isClosedManifold()) << d.describe();
    EXPECT_GT(d.signedVolume, 0.0);
    EXPECT_NEAR(d.signedVolume / body.massProperties().volume, 1.0, 0.01);
}

}  // namespace
}  // namespace btfracture
