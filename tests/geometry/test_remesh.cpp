// SPDX-License-Identifier: Zlib
// BEM remeshing (geometry/Remesh.h) and its parts: half-edge edits, closest-point queries,
// quality measures and surface distances.
#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/core/SelfIntersection.h>
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/HalfEdgeMesh.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/geometry/MeshQuality.h>
#include <btFracture/geometry/Remesh.h>
#include <btFracture/geometry/SurfaceDistance.h>
#include <btFracture/io/MeshReader.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <tuple>

using namespace btfracture;

namespace {

const TriangleMesh& bunny() {
    static const TriangleMesh mesh = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/bunny.obj");
    return mesh;
}

const TriangleMesh& armadillo() {
    static const TriangleMesh mesh = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/armadillo.obj");
    return mesh;
}

double bboxDiagonal(const TriangleMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const auto& v : mesh.vertices) box.extend(v);
    return box.diagonal().norm();
}

int eulerCharacteristic(const TriangleMesh& mesh) {
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
    return static_cast<int>(mesh.vertices.size()) - static_cast<int>(edges.size()) +
           static_cast<int>(mesh.triangles.size());
}

struct RemeshTolerances {
    double hausdorff;  // relative to the input's bounding-box diagonal
    double volume;     // relative to the input's volume
};

// Remeshes `input` and checks every acceptance point of the BEM mesh; prints what it measured.
TriangleMesh checkBemMesh(const TriangleMesh& input, int target, const RemeshTolerances& tolerance) {
    const TriangleMesh output = remeshForBem(input, target);
    const MeshDefects defects = inspectMesh(output);
    EXPECT_TRUE(defects.isClosedSolid()) << input.name << " @ " << target << ": " << defects.describe();
    EXPECT_EQ(defects.components, inspectMesh(input).components);
    EXPECT_EQ(eulerCharacteristic(output), eulerCharacteristic(input)) << "genus changed";

    const MeshQuality quality = measureQuality(output, 20.0);
    const int count = quality.triangleCount;
    EXPECT_NEAR(count, target, 0.1 * target) << input.name;
    EXPECT_GE(quality.minAngleDegrees, 20.0) << input.name << " @ " << target;
    EXPECT_EQ(quality.trianglesBelowAngle, 0);

    const double hausdorff = hausdorffDistance(input, output) / bboxDiagonal(input);
    EXPECT_LT(hausdorff, tolerance.hausdorff) << input.name << " @ " << target;
    const double volumeError = defects.signedVolume / inspectMesh(input).signedVolume - 1.0;
    EXPECT_LT(std::abs(volumeError), tolerance.volume) << input.name << " @ " << target;

    std::printf(
        "  %-10s target %5d: %5d triangles (%+.1f %%), min angle %.1f deg (mean of minima %.1f), max angle "
        "%.1f deg, Hausdorff %.4f of bbox diagonal, volume %+.2f %%\n",
        input.name.substr(input.name.find_last_of('/') + 1).c_str(), target, count,
        100.0 * (count - target) / target, quality.minAngleDegrees, quality.meanMinAngleDegrees,
        quality.maxAngleDegrees, hausdorff, 100.0 * volumeError);
    return output;
}

}  // namespace

// ---- Acceptance: BEM meshes of the test shapes --------------------------------------------------

// Every shipped mesh (demos/meshes/*.obj, each part of the teapot a closed shell of its own)
// gets a valid BEM mesh at 1,000 triangles: closed, intersection-free, every angle >= 20
// degrees, as many parts as the input, within 10 % of the target. The teapot is the exception
// to the count: its walls are 0.85 units thick on a pot 96 across (0.9 %), 13 times thinner
// than the uniform edge length, and its rims, spout and handle need edges of about 1-3 units;
// no mesh of 1,000 triangles keeps the two sides of its walls apart (measured: 461 intersecting
// pairs within the target), so the thin parts get their own lengths and the count grows
// (4,804 measured; allowed up to 6,000).
TEST(Remesh, EveryShippedMeshAtOneThousandTriangles) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(BTFRACTURE_MESH_DIR))
        if (entry.path().extension() == ".obj") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 7u);
    for (const std::string& file : files) {
        const TriangleMesh input = readMesh(file);
        const TriangleMesh output = remeshForBem(input, 1000);
        const MeshDefects defects = inspectMesh(output);
        EXPECT_TRUE(defects.isClosedSolid()) << file << ": " << defects.describe();
        EXPECT_EQ(defects.components, inspectMesh(input).components) << file;
        const MeshQuality quality = measureQuality(output, 20.0);
        const bool teapot = std::filesystem::path(file).filename() == "teapot.obj";
        EXPECT_GE(quality.triangleCount, 900) << file;
        EXPECT_LE(quality.triangleCount, teapot ? 6000 : 1100) << file;
        EXPECT_GE(quality.minAngleDegrees, 20.0) << file;
        std::printf("  %-12s %5d triangles, %d intersecting pairs, min angle %.1f deg, edges %.3g-%.3g\n",
                    std::filesystem::path(file).filename().c_str(), quality.triangleCount,
                    defects.intersectingPairs, quality.minAngleDegrees, quality.minEdgeLength,
                    quality.maxEdgeLength);
    }
}

// Mean length of the edges along the rim of a pane 0.6 x 0.4 m centred at the origin (both ends
// within 2 mm of its side planes |x| = 0.3, |y| = 0.2) and of those in the middle of its faces
// (both ends more than 5 cm inside the rim).
std::pair<double, double> paneEdgeLengths(const TriangleMesh& mesh) {
    auto inset = [](const Eigen::Vector3d& p) {
        return std::min(0.3 - std::abs(p.x()), 0.2 - std::abs(p.y()));
    };
    double rim = 0.0, face = 0.0;
    int rimEdges = 0, faceEdges = 0;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d &a = mesh.vertices[t[k]], &b = mesh.vertices[t[(k + 1) % 3]];
            if (inset(a) < 0.002 && inset(b) < 0.002) rim += (a - b).norm(), ++rimEdges;
            if (inset(a) > 0.05 && inset(b) > 0.05) face += (a - b).norm(), ++faceEdges;
        }
    EXPECT_GT(rimEdges, 0);
    EXPECT_GT(faceEdges, 0);
    return {rim / std::max(1, rimEdges), face / std::max(1, faceEdges)};
}

// A 6 mm window pane (0.6 x 0.4 x 0.006 m) gets a valid BEM mesh at 3,000 triangles, uniform
// (the default: it does not intersect) or with the thickness sizing first: shorter edges along
// its rim (where the surface turns through 180 degrees within 6 mm) than on its faces, and
// shorter there than the uniform mesh of the same count has.
TEST(Remesh, SixMillimetrePaneWithinThreeThousandTriangles) {
    TriangleMesh pane = makeBox(Eigen::Vector3d(0.3, 0.2, 0.003));
    pane.name = "6 mm pane";
    RemeshOptions sized;
    sized.thicknessSizing = RemeshOptions::ThicknessSizing::Always;
    const TriangleMesh output = remeshForBem(pane, 3000, sized);
    const MeshDefects defects = inspectMesh(output);
    EXPECT_TRUE(defects.isClosedSolid()) << defects.describe();
    const MeshQuality quality = measureQuality(output, 20.0);
    EXPECT_NEAR(quality.triangleCount, 3000, 300);
    EXPECT_GE(quality.minAngleDegrees, 20.0);
    const auto [rim, face] = paneEdgeLengths(output);
    EXPECT_LT(rim, 0.015);       // at most 2.5 times the thickness (measured 14.3 mm)
    EXPECT_GT(face, 1.3 * rim);  // the faces keep longer edges (measured 21.3 mm)
    std::printf(
        "  6 mm pane: %d triangles, %d intersecting pairs, min angle %.1f deg, mean edge on the rim "
        "%.4f m, in the faces %.4f m\n",
        quality.triangleCount, defects.intersectingPairs, quality.minAngleDegrees, rim, face);
    RemeshOptions uniform;
    uniform.thicknessSizing = RemeshOptions::ThicknessSizing::Never;
    const TriangleMesh plain = remeshForBem(pane, 3000, uniform);
    EXPECT_TRUE(inspectMesh(plain).isClosedSolid());  // the default keeps this one
    const double plainRim = paneEdgeLengths(plain).first;
    EXPECT_LT(rim, 0.9 * plainRim);  // measured 0.84
    std::printf("  uniform mesh of the same count: mean edge on the rim %.4f m\n", plainRim);
}

// A remesh that outlasts its time budget fails with an error naming the mesh, the budget and
// the stage it was in, instead of running on.
TEST(Remesh, TimeBudgetEndsARemeshWithAClearError) {
    RemeshOptions options;
    options.timeBudgetSeconds = 1e-6;
    try {
        remeshForBem(bunny(), 1000, options);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("bunny"), std::string::npos) << message;
        EXPECT_NE(message.find("time budget of 1e-06 s"), std::string::npos) << message;
        EXPECT_NE(message.find("during isotropic remeshing"), std::string::npos) << message;
    }
    options.timeBudgetSeconds = 0.0;
    EXPECT_THROW(remeshForBem(bunny(), 500, options), Error);
}

// A fragment's BEM source that folds onto itself: the local refinement around its intersecting
// triangles split one edge again and again (the same length back after every split) until memory
// ran out. The refinement now stops there and the later passes separate the triangles.
TEST(Remesh, FoldedSourceEndsWithoutRunawaySplitting) {
    TriangleMesh input = readMesh(std::string(BTFRACTURE_TEST_DATA_DIR) + "/remesh/folded_bem_source.obj");
    input.name = "folded source";
    RemeshOptions options;  // as BemFractureEngine builds a fragment's BEM
    options.maxRefinements = 1;
    options.thicknessSizing = RemeshOptions::ThicknessSizing::WhenUniformFails;
    const TriangleMesh output = remeshForBem(input, 1500, options);
    const MeshDefects defects = inspectMesh(output);
    EXPECT_TRUE(defects.isClosedSolid()) << defects.describe();
    EXPECT_EQ(defects.intersectingPairs, 0);
    EXPECT_LT(output.triangles.size(), 3000u);  // measured 1,870
}

TEST(Remesh, BunnyAtThreeResolutions) {
    checkBemMesh(bunny(), 500, {0.05, 0.02});
    checkBemMesh(bunny(), 1000, {0.035, 0.01});
    checkBemMesh(bunny(), 3000, {0.02, 0.005});
}

TEST(Remesh, ArmadilloAtThreeResolutions) {
    checkBemMesh(armadillo(), 500, {0.05, 0.05});
    checkBemMesh(armadillo(), 1000, {0.035, 0.025});
    checkBemMesh(armadillo(), 3000, {0.03, 0.01});
}

TEST(Remesh, SphereAtThreeResolutions) {
    TriangleMesh sphere = makeGeodesicSphere(1.0, 32);
    sphere.name = "sphere";
    checkBemMesh(sphere, 500, {0.01, 0.005});
    checkBemMesh(sphere, 1000, {0.01, 0.003});
    checkBemMesh(sphere, 3000, {0.005, 0.002});
}

TEST(Remesh, BoxAtThreeResolutions) {
    // Sharp edges and corners are not tracked: they are rounded over about one edge length L.
    // A corner cut off at L along its three edges lies L / sqrt(3) = 0.58 L from the corner;
    // measured 0.34-0.44 L (Release and -O2 builds differ here: the box's equal edges make ties
    // that rounding breaks), so the Hausdorff limit is half the nominal edge length.
    TriangleMesh box = makeBox(Eigen::Vector3d(1.0, 0.5, 0.25));
    box.name = "box";
    const double area = surfaceArea(box), diagonal = bboxDiagonal(box);
    for (const auto& [target, volume] : {std::pair{500, 0.03}, {1000, 0.02}, {3000, 0.01}}) {
        const double edge = std::sqrt(4.0 * area / (std::sqrt(3.0) * target));
        checkBemMesh(box, target, {0.5 * edge / diagonal, volume});
    }
}

TEST(Remesh, FineLevelSetMeshes) {
    // The BEM mesh of a fragment comes from a level-set surface with ~10^5 triangles. At 256
    // voxels across, the armadillo's claws are closer together than the edge length of a
    // 3,000-triangle mesh: the remesher refines there instead of leaving intersections.
    for (const auto& [mesh, voxelsAcross, target] :
         {std::tuple{&bunny(), 128, 1000}, std::tuple{&armadillo(), 256, 3000}}) {
        Eigen::AlignedBox3d box;
        for (const auto& v : mesh->vertices) box.extend(v);
        TriangleMesh fine = LevelSetBody(*mesh, box.sizes().maxCoeff() / voxelsAcross).visualMesh();
        fine.name = mesh->name + " level set";
        EXPECT_GT(fine.triangles.size(), 90000u);
        const TriangleMesh output = checkBemMesh(fine, target, {0.03, 0.01});
        const double toOriginal = hausdorffDistance(*mesh, output) / bboxDiagonal(*mesh);
        EXPECT_LT(toOriginal, 0.03);
        std::printf("  (Hausdorff to the original mesh %.4f)\n", toOriginal);
    }
}

TEST(Remesh, ThinTorusKeepsItsHandle) {
    // Tube circumference ~3 edge lengths: collapses must not pinch the handle shut.
    const TriangleMesh torus = makeTorus(1.0, 0.12, 96, 24);
    const TriangleMesh output = remeshForBem(torus, 300);
    const MeshDefects defects = inspectMesh(output);
    EXPECT_TRUE(defects.isClosedManifold()) << defects.describe();
    EXPECT_EQ(eulerCharacteristic(output), 0);
    EXPECT_GE(measureQuality(output).minAngleDegrees, 20.0);
}

TEST(Remesh, SphereVolumeConvergesToFourThirdsPi) {
    TriangleMesh sphere = makeGeodesicSphere(1.0, 64);
    sphere.name = "sphere";
    const double exact = 4.0 / 3.0 * M_PI;
    // Vertices on the sphere (no surface fit): the inscribed polyhedron misses a volume
    // proportional to L^2 ~ 1 / N, so four times the triangles leave about a quarter of the error.
    RemeshOptions onSurface;
    onSurface.fitAcrossSurface = false;
    double previous = INFINITY;
    for (int target : {250, 1000, 4000}) {
        const double error = exact - computeMassProperties(remeshForBem(sphere, target, onSurface)).volume;
        EXPECT_GT(error, 0.0) << "an inscribed mesh has less volume";
        if (std::isfinite(previous)) {
            EXPECT_GT(previous / error, 3.0) << target;
            EXPECT_LT(previous / error, 5.5) << target;
        }
        std::printf("  inscribed sphere, target %4d: volume error %.3e (%.3f %%)\n", target, error,
                    100 * error / exact);
        previous = error;
    }
    // With the surface fit the volume error is far smaller at every resolution.
    for (int target : {250, 1000, 4000}) {
        const double error = std::abs(exact - computeMassProperties(remeshForBem(sphere, target)).volume);
        EXPECT_LT(error / exact, 2e-3) << target;
        std::printf("  fitted sphere,    target %4d: volume error %.3e (%.3f %%)\n", target, error,
                    100 * error / exact);
    }
}

TEST(Remesh, IsDeterministic) {
    const TriangleMesh a = remeshForBem(bunny(), 800);
    const TriangleMesh b = remeshForBem(bunny(), 800);
    ASSERT_EQ(a.triangles, b.triangles);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
}

TEST(Remesh, RejectsBadInput) {
    TriangleMesh open = bunny();
    open.name = "open bunny";
    open.triangles.pop_back();
    try {
        remeshForBem(open, 500);
        FAIL() << "open mesh accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("open bunny"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("boundary edges"), std::string::npos) << e.what();
    }
    try {
        remeshForBem(bunny(), 12);
        FAIL() << "target of 12 triangles accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("12 triangles is below the minimum of 20"), std::string::npos)
            << e.what();
    }
    RemeshOptions options;
    options.minAngleDegrees = 50.0;
    EXPECT_THROW(remeshForBem(bunny(), 500, options), Error);
    options = {};
    options.iterations = 0;
    EXPECT_THROW(remeshForBem(bunny(), 500, options), Error);
    options = {};
    options.smoothingStep = 0.0;
    EXPECT_THROW(remeshForBem(bunny(), 500, options), Error);
    EXPECT_THROW(remeshForBem(TriangleMesh{}, 500), Error);
}

// ---- Parts ---------------------------------------------------------------------------------------

TEST(MeshQuality, KnownAngles) {
    TriangleMesh right;
    right.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    right.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const MeshQuality q = measureQuality(right, 50.0);
    EXPECT_NEAR(q.minAngleDegrees, 45.0, 1e-12);
    EXPECT_NEAR(q.maxAngleDegrees, 90.0, 1e-12);
    EXPECT_NEAR(q.meanMinAngleDegrees, (3 * 45.0 + 60.0) / 4, 1e-12);
    EXPECT_EQ(q.trianglesBelowAngle, 3);
    EXPECT_NEAR(q.minEdgeLength, 1.0, 1e-15);
    EXPECT_NEAR(q.maxEdgeLength, std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(q.edgeLengthRatio, std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(q.meanEdgeLength, (3 + 3 * std::sqrt(2.0)) / 6, 1e-15);
    EXPECT_THROW(measureQuality(TriangleMesh{}), Error);
}

TEST(ClosestPointTree, MatchesBruteForce) {
    const TriangleMesh& mesh = bunny();
    const ClosestPointTree tree(mesh);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-8.0, 12.0);
    for (int i = 0; i < 300; ++i) {
        const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
        double best = INFINITY;
        for (const auto& t : mesh.triangles)
            best = std::min(
                best,
                (closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) - p)
                    .squaredNorm());
        const ClosestPointTree::Hit hit = tree.closestPoint(p);
        EXPECT_EQ(hit.squaredDistance, best);
        EXPECT_NEAR((hit.point - p).squaredNorm(), hit.squaredDistance, 1e-12);
    }
}

TEST(ClosestPointTree, NormalFilterKeepsPointsOnTheirSide) {
    // A thin slab 0.02 thick: a point just above the bottom face, with an upward normal (the
    // top face's side), must land on the top face, not on the nearer bottom face.
    TriangleMesh slab = makeBox(Eigen::Vector3d(1.0, 1.0, 0.01));
    const ClosestPointTree tree(slab);
    const Eigen::Vector3d p(0.3, 0.2, -0.009);
    EXPECT_NEAR(tree.closestPoint(p).point.z(), -0.01, 1e-15);
    EXPECT_NEAR(tree.closestPoint(p, Eigen::Vector3d::UnitZ(), 0.0).point.z(), 0.01, 1e-15);
}

TEST(SurfaceDistance, ConcentricSpheres) {
    const TriangleMesh inner = makeGeodesicSphere(1.0, 16), outer = makeGeodesicSphere(1.1, 16);
    // Same triangulation scaled: the distance is 0.1 at the vertices and a little more at the
    // face centres of the outer mesh (which are inside its sphere by the chord depth).
    const double d = hausdorffDistance(inner, outer);
    EXPECT_GT(d, 0.1 - 1e-12);
    EXPECT_LT(d, 0.1 + 0.005);
    EXPECT_NEAR(hausdorffDistance(inner, inner), 0.0, 1e-12);
}

TEST(HalfEdgeMesh, EditsKeepAClosedManifold) {
    HalfEdgeMesh mesh(makeGeodesicSphere(1.0, 8));
    const int chi = 2;
    std::mt19937 random(3);
    int splits = 0, flips = 0, collapses = 0;
    for (int step = 0; step < 3000; ++step) {
        const int h = std::uniform_int_distribution<int>(0, mesh.halfedgeSlots() - 1)(random);
        if (!mesh.halfedgeAlive(h)) continue;
        switch (step % 3) {
            case 0:
                mesh.splitEdge(h, 0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h))));
                ++splits;
                break;
            case 1:
                if (mesh.flipKeepsManifold(h)) {
                    mesh.flipEdge(h);
                    ++flips;
                }
                break;
            default:
                if (mesh.collapseKeepsManifold(h)) {
                    mesh.collapseEdge(h, mesh.position(mesh.target(h)));
                    ++collapses;
                }
        }
        if (step % 500 == 0) mesh.compact();
    }
    EXPECT_GT(splits, 500);
    EXPECT_GT(flips, 500);
    EXPECT_GT(collapses, 500);
    const TriangleMesh out = mesh.toTriangleMesh("edited");
    const MeshDefects d = inspectMesh(out);
    EXPECT_EQ(d.boundaryEdges + d.nonManifoldEdges + d.nonManifoldVertices + d.inconsistentEdges, 0)
        << d.describe();
    EXPECT_EQ(eulerCharacteristic(out), chi);
    EXPECT_EQ(static_cast<int>(out.triangles.size()), mesh.faceCount());
    EXPECT_EQ(static_cast<int>(out.vertices.size()), mesh.vertexCount());
}

// A tetrahedron beside another closed component (debris in a fragment's level-set mesh): the
// mesh has more than 4 vertices and each tetrahedron edge passes the link condition, but a
// collapse would leave two faces back to back whose vertices have two neighbours each (a later
// edit then corrupted the half-edge rings: a heap overflow in the stability suite).
TEST(HalfEdgeMesh, TetrahedronBesideAnotherComponentIsNotCollapsed) {
    TriangleMesh two;
    two.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
    two.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}, {5, 6, 7}};
    const HalfEdgeMesh mesh(two);
    ASSERT_EQ(mesh.vertexCount(), 8);
    for (int h = 0; h < mesh.halfedgeSlots(); ++h)
        EXPECT_FALSE(mesh.collapseKeepsManifold(h)) << "halfedge " << h;
}

TEST(HalfEdgeMesh, LinkConditionStopsTetrahedronCollapse) {
    TriangleMesh tetra;
    tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const HalfEdgeMesh mesh(tetra);
    for (int h = 0; h < mesh.halfedgeSlots(); ++h) {
        EXPECT_FALSE(mesh.collapseKeepsManifold(h));
        EXPECT_FALSE(mesh.flipKeepsManifold(h));  // the new edge would duplicate an existing one
    }
}
