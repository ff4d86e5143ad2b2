// SPDX-License-Identifier: Zlib
// FractureRB compatibility: the shipped example, every shape kind the reader converts (written
// here with btDefaultSerializer), and clear errors for malformed parameter rows.
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/io/FractureRbScene.h>
#include <btFracture/io/SceneWorld.h>

#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

const std::string kExample = std::string(BTFRACTURE_MESH_DIR) + "/../fracturerb/brick_shot";
const double kFloat = std::is_same<btScalar, float>::value ? 1e-6 : 1e-12;  // stored precision

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "btfracture_test_fracturerb";
    std::filesystem::create_directories(dir);
    return dir / name;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

const SceneBody& bodyNamed(const Scene& scene, const std::string& name) {
    for (const SceneBody& b : scene.bodies)
        if (b.name == name) return b;
    throw std::runtime_error("no body " + name);
}

std::string errorOfCsv(const std::string& csv) {
    try {
        parseFractureRbCsv(csv, "params.csv");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

// The example: names from the CSV, shapes, poses, masses, velocities, states and materials as
// written by demos/fracturerb/make_fracturerb_example.cpp.
TEST(FractureRb, ExampleMatchesItsGenerator) {
    const Scene scene = readFractureRbScene(kExample + ".bullet", kExample + ".csv");
    EXPECT_EQ(scene.name, "brick_shot");
    ASSERT_EQ(scene.bodies.size(), 4u);
    EXPECT_NEAR((scene.world.gravity - Eigen::Vector3d(0, -9.81, 0)).norm(), 0.0, 1e-6);
    EXPECT_DOUBLE_EQ(scene.world.dt, 1.0 / 250.0);
    EXPECT_EQ(scene.world.steps, 1000);
    EXPECT_TRUE(scene.effects.outputs.motion && scene.effects.outputs.gltf && scene.effects.outputs.csv &&
                scene.effects.outputs.png);
    EXPECT_FALSE(scene.effects.outputs.obj);

    const SceneBody& ground = bodyNamed(scene, "pGround");  // no CSV row: the file's name
    EXPECT_EQ(ground.shape.type, SceneShapeType::Box);
    EXPECT_NEAR((ground.shape.halfExtents - Eigen::Vector3d(5, 0.5, 5)).norm(), 0.0, 1e-6);
    EXPECT_TRUE(ground.isStatic());
    EXPECT_NEAR(ground.position.y(), -0.5, 1e-7);
    EXPECT_NEAR(ground.friction, 0.8, 1e-7);

    const SceneBody& brick = bodyNamed(scene, "brick");  // renamed from pBrick1
    EXPECT_EQ(brick.shape.type, SceneShapeType::Mesh);
    ASSERT_TRUE(brick.shape.meshData);
    EXPECT_EQ(brick.shape.meshData->triangles.size(), 56u);  // 4 x 1 x 2 cells, two triangles each
    EXPECT_NEAR(computeMassProperties(*brick.shape.meshData).volume, 0.24 * 0.07 * 0.115, 1e-9);
    EXPECT_FALSE(brick.isStatic());        // the importer made it static; the file's record restores it
    EXPECT_FALSE(brick.mass.has_value());  // breakable: mass from density x volume, as FractureRB
    EXPECT_DOUBLE_EQ(brick.density, 2300.0);
    EXPECT_DOUBLE_EQ(brick.material.youngsModulus(), 30e9);
    EXPECT_DOUBLE_EQ(brick.material.poissonRatio(), 0.2);
    EXPECT_DOUBLE_EQ(brick.material.tensileStrength(), 1e6);
    EXPECT_DOUBLE_EQ(brick.material.fractureToughness(), 2e5);
    EXPECT_DOUBLE_EQ(brick.material.compressiveFactor(), 10.0);
    EXPECT_TRUE(brick.fracture.fracturable);
    EXPECT_EQ(brick.fracture.method, FractureMethod::Full);
    EXPECT_EQ(brick.fracture.bemTriangleTarget, 800);  // the row's remesh target
    EXPECT_DOUBLE_EQ(brick.fracture.voxelSize, 0.002);
    EXPECT_DOUBLE_EQ(brick.fracture.crackElementSize, 0.025);  // column 10, the crack mesh size [m]
    EXPECT_NEAR((brick.position - Eigen::Vector3d(0, 0.035, 0)).norm(), 0.0, 1e-7);

    const SceneBody& ball = bodyNamed(scene, "ball");
    EXPECT_EQ(ball.shape.type, SceneShapeType::Sphere);
    EXPECT_NEAR(ball.shape.radius, 0.04, 1e-7);
    ASSERT_TRUE(ball.mass.has_value());
    EXPECT_NEAR(*ball.mass, 2.1, 1e-6);  // rigid: the file's mass
    EXPECT_EQ(ball.linearVelocity, Eigen::Vector3d(15, 0.5, 0));
    EXPECT_EQ(ball.angularVelocity, Eigen::Vector3d(0, 0, 5));
    EXPECT_FALSE(ball.fracture.fracturable);
    EXPECT_EQ(ball.motion, SceneMotion::Dynamic);

    const SceneBody& rock = bodyNamed(scene, "rock");
    EXPECT_EQ(rock.motion, SceneMotion::Sleeping);
    ASSERT_TRUE(rock.shape.meshData);
    EXPECT_EQ(rock.shape.meshData->triangles.size(), 8u);  // the octahedron's hull

    // The scene builds and steps like a JSON scene: the brick weighs density x volume.
    SceneWorld world(scene);
    const btRigidBody& brickBody = *world.bodies()[1].rigidBody;
    EXPECT_NEAR(1.0 / brickBody.getInvMass(), 2300.0 * 0.24 * 0.07 * 0.115, 1e-3);
    for (int i = 0; i < 10; ++i) world.stepFrame();
    EXPECT_GT(world.bodies()[2].rigidBody->getCenterOfMassPosition().x(), -0.6);  // the ball flies
}

// Shapes the reader converts, written by this test: a compound with one offset child, a tilted
// static plane, a GImpact body (Bullet's importer drops those: rebuilt from the file), a
// kinematic convex hull, and a scaled BVH mesh.
TEST(FractureRb, ConvertsEveryShapeKind) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, -3));

    const TriangleMesh cube = makeBox(Eigen::Vector3d(0.5, 0.5, 0.5));
    std::vector<btScalar> vertices;
    std::vector<int> indices;
    for (const auto& v : cube.vertices)
        for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<btScalar>(v[k]));
    for (const auto& t : cube.triangles) indices.insert(indices.end(), t.begin(), t.end());
    btTriangleIndexVertexArray cubeData(static_cast<int>(cube.triangles.size()), indices.data(),
                                        3 * sizeof(int), static_cast<int>(cube.vertices.size()),
                                        vertices.data(), 3 * sizeof(btScalar));

    btBoxShape childBox(btVector3(1, 2, 3));
    btCompoundShape compound;
    compound.addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 4)), &childBox);
    btStaticPlaneShape plane(btVector3(0, 0, 1), 2);
    btGImpactMeshShape gimpact(&cubeData);
    gimpact.setLocalScaling(btVector3(2, 2, 2));
    gimpact.updateBound();
    btConvexHullShape hull;
    for (const auto& v : cube.vertices)
        hull.addPoint(btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())), false);
    hull.recalcLocalAabb();
    btBvhTriangleMeshShape bvh(&cubeData, true);
    btScaledBvhTriangleMeshShape scaled(&bvh, btVector3(3, 1, 1));

    struct Entry {
        const char* name;
        btCollisionShape* shape;
        btScalar mass;
        btTransform pose;
    };
    const btQuaternion tilt(btVector3(1, 0, 0), btScalar(0.3));
    const Entry entries[] = {
        {"compound", &compound, 2, btTransform(btQuaternion::getIdentity(), btVector3(10, 0, 0))},
        {"slope", &plane, 0, btTransform(tilt, btVector3(0, 0, 0))},
        {"gimpact", &gimpact, 5, btTransform(btQuaternion::getIdentity(), btVector3(0, 7, 1))},
        {"hull", &hull, 1, btTransform(btQuaternion::getIdentity(), btVector3(-4, 0, 1))},
        {"scaled", &scaled, 0, btTransform(btQuaternion::getIdentity(), btVector3(0, -9, 0))},
    };
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    for (const Entry& e : entries) {
        btRigidBody::btRigidBodyConstructionInfo info(e.mass, nullptr, e.shape, btVector3(1, 1, 1));
        info.m_startWorldTransform = e.pose;
        bodies.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(bodies.back().get());
    }
    bodies[2]->setLinearVelocity(btVector3(0, 0, 2));  // the GImpact body's velocity comes from its record
    bodies[3]->setCollisionFlags(bodies[3]->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    btDefaultSerializer serializer;
    serializer.startSerialization();
    for (size_t i = 0; i < bodies.size(); ++i)
        serializer.registerNameForPointer(bodies[i].get(), entries[i].name);
    world.serialize(&serializer);
    const auto file = scratch("shapes.bullet");
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(serializer.getBufferPointer()),
               serializer.getCurrentBufferSize());
    for (auto& b : bodies) world.removeRigidBody(b.get());
    const auto csv = scratch("shapes.csv");
    writeText(csv, "% no parameters\n");

    const Scene scene = readFractureRbScene(file.string(), csv.string());
    ASSERT_EQ(scene.bodies.size(), 5u);
    EXPECT_NEAR((scene.world.gravity - Eigen::Vector3d(0, 0, -3)).norm(), 0.0, 1e-6);

    const SceneBody& c = bodyNamed(scene, "compound");
    EXPECT_EQ(c.shape.type, SceneShapeType::Box);
    EXPECT_NEAR((c.shape.halfExtents - Eigen::Vector3d(1, 2, 3)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((c.position - Eigen::Vector3d(10, 0, 4)).norm(), 0.0, 1e-6);  // the child's offset folded in
    EXPECT_NEAR(*c.mass, 2.0, 1e-6);

    const SceneBody& slope = bodyNamed(scene, "slope");
    EXPECT_EQ(slope.shape.type, SceneShapeType::Plane);
    const Eigen::Vector3d tilted =
        Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
    EXPECT_NEAR((slope.shape.normal - tilted).norm(), 0.0, 1e-6);
    EXPECT_NEAR(slope.shape.offset, 2.0, 1e-6);

    const SceneBody& g = bodyNamed(scene, "gimpact");
    ASSERT_TRUE(g.shape.meshData);
    EXPECT_EQ(g.shape.meshData->triangles.size(), 12u);
    EXPECT_NEAR(computeMassProperties(*g.shape.meshData).volume, 8.0, 1e-4);  // scaled by 2
    EXPECT_NEAR(*g.mass, 5.0, 1e-5);
    EXPECT_NEAR((g.linearVelocity - Eigen::Vector3d(0, 0, 2)).norm(), 0.0, kFloat);
    EXPECT_NEAR((g.position - Eigen::Vector3d(0, 7, 1)).norm(), 0.0, 1e-6);

    const SceneBody& h = bodyNamed(scene, "hull");
    EXPECT_EQ(h.motion, SceneMotion::Kinematic);
    ASSERT_TRUE(h.shape.meshData);
    EXPECT_NEAR(computeMassProperties(*h.shape.meshData).volume, 1.0, 1e-5);  // outward-oriented hull

    const SceneBody& s = bodyNamed(scene, "scaled");
    EXPECT_TRUE(s.isStatic());
    EXPECT_NEAR(computeMassProperties(*s.shape.meshData).volume, 3.0, 1e-4);

    SceneWorld built(scene);  // every converted mesh is a valid closed solid
    EXPECT_EQ(built.bodies().size(), 5u);
}

// Every malformed row names the file, the line, the column and what was expected.
TEST(FractureRb, MalformedRowsNameFileLineAndColumn) {
    const std::string breakable = "pCube1;cube;0;0;0;0;0;0;0;0.1;0.01;1e9;0.3;1000;1e6;1e5;3;0;0;default";
    const std::pair<std::string, std::string> cases[] = {
        {"% header\n\npCube1;cube;1;2\n",
         "params.csv:3: a row has 2 columns (name, new name), 9 (plus velocities and state) or 20 to 23 (a "
         "breakable body), got 4"},
        {"pCube1;cube;1;2;x;0;0;0;0\n",
         "params.csv:1: column 5 (linear velocity z): expected a number [m/s], got 'x'"},
        {"pCube1;cube;1;2;3;0;0;1e999;0\n",
         "params.csv:1: column 8 (angular velocity z): expected a number [rad/s], got '1e999'"},
        {"pCube1;cube;1;2;3;0;0;0;3\n",
         "params.csv:1: column 9 (state): expected 0 (dynamic), 1 (sleeping) or 2 (kinematic), got '3'"},
        {"pCube1;my cube\n",
         "params.csv:1: column 2 (new name): expected a non-empty name without spaces, got 'my cube'"},
        {";cube\n", "params.csv:1: column 1 (object name): expected a non-empty name without spaces, got ''"},
        {"pCube1;cube;0;0;0;0;0;0;0;-0.1;0.01;1e9;0.3;1000;1e6;1e5;3;0;0;default\n",
         "params.csv:1: column 10 (crack mesh size): expected a positive number [m], got '-0.1'"},
        {"pCube1;cube;0;0;0;0;0;0;0;0.1;0.01;1e9;0.7;1000;1e6;1e5;3;0;0;default\n",
         "params.csv:1: columns 12-17 (material): material 'cube': Poisson ratio nu must lie in (-1, 0.5), "
         "got 0.7"},
        {"pCube1;cube;0;0;0;0;0;0;0;0.1;0.01;1e9;0.3;1000;1e6;1e5;3;2.5;0;default\n",
         "params.csv:1: column 18 (remesh target): expected an integer [triangles], got '2.5'"},
        {breakable + ";-1;2\n",
         "params.csv:1: column 22 (method): expected 0 (full BEM) or 1 (estimated SIFs), got '2'"},
        {breakable + ";-1;0;0\n",
         "params.csv:1: column 23 (sampling density): expected a positive number [samples per crack-front "
         "edge], got '0'"},
        {breakable + ";-1;0;1;7\n", "params.csv:1: a row has 2 columns"},
        {"pCube1;a\n% again:\npCube1;b\n",
         "params.csv:3: column 1 (object name): 'pCube1' already has a row (line 1)"},
    };
    for (const auto& [csv, expected] : cases) {
        const std::string message = errorOfCsv(csv);
        EXPECT_NE(message.find(expected), std::string::npos)
            << "expected: " << expected << "\n     got: " << message;
    }
}

// The parser's leniencies match FractureRB's: blanks around fields, comments after a field, a
// trailing ';', Windows line ends.
TEST(FractureRb, CsvLayoutAsFractureRbWritesIt) {
    const auto objects = parseFractureRbCsv(
        "% comment\r\n  pA ; a ;1; 2 ;3;0;0;0;1; % trailing comment\r\npB;b;\n"
        "pC;c;0;0;0;0;0;0;0;0.1;0.01;1e9;0.3;1000;1e6;1e5;3;500;1;lay(0,1,0,2,1,1);4;1;2\n",
        "p.csv");
    ASSERT_EQ(objects.size(), 3u);
    EXPECT_EQ(objects[0].name, "a");
    EXPECT_EQ(*objects[0].linearVelocity, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(objects[0].motion, SceneMotion::Sleeping);
    EXPECT_EQ(objects[0].line, 2);
    EXPECT_FALSE(objects[1].linearVelocity.has_value());
    ASSERT_TRUE(objects[2].breakable.has_value());
    EXPECT_EQ(objects[2].breakable->remeshTarget, 500);
    EXPECT_TRUE(objects[2].breakable->ignoreCrackSelfIntersection);
    EXPECT_EQ(objects[2].breakable->materialModel, "lay(0,1,0,2,1,1)");
    EXPECT_EQ(objects[2].breakable->maxCracks, 4);
    EXPECT_EQ(objects[2].breakable->method, FractureMethod::Estimated);
    EXPECT_DOUBLE_EQ(objects[2].breakable->samplingDensity, 2.0);
}

// Errors that need the .bullet file: a row for an object the file does not have, a static object
// given a velocity, files that are missing or not Bullet files.
TEST(FractureRb, FileLevelErrors) {
    auto errorOf = [](const std::string& bullet, const std::string& csvText) {
        const auto csv = scratch("errors.csv");
        writeText(csv, csvText);
        try {
            readFractureRbScene(bullet, csv.string());
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    const std::string example = kExample + ".bullet";
    EXPECT_NE(errorOf(example, "pBrik1;brick\n")
                  .find("errors.csv:1: column 1 (object name): no object named 'pBrik1' in " + example +
                        " (objects: pBrick1, pGround, pRock1, pSphere1)"),
              std::string::npos);
    EXPECT_NE(errorOf(example, "pGround;ground;1;0;0;0;0;0;0\n")
                  .find("errors.csv:1: columns 3-8 (velocities): object 'pGround' is static and cannot move"),
              std::string::npos);
    EXPECT_NE(errorOf(example, "pBrick1;pGround\n")
                  .find("errors.csv:1: column 2 (new name): the name 'pGround' is already taken"),
              std::string::npos);
    const auto garbage = scratch("garbage.bullet");
    writeText(garbage, "PK\x03\x04 a zip file, not a world");
    EXPECT_NE(errorOf(garbage.string(), "").find("garbage.bullet: not a Bullet world file"),
              std::string::npos);
    writeText(garbage, "BULLETd_0 header only");
    EXPECT_NE(errorOf(garbage.string(), "")
                  .find("garbage.bullet: no rigid bodies or collision objects in the file"),
              std::string::npos);
    EXPECT_NE(errorOf("no/such.bullet", "").find("cannot open Bullet file 'no/such.bullet'"),
              std::string::npos);
}
