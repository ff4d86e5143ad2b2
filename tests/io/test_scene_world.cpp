// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/MeshReader.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace btfracture;

namespace {

const std::string kData = BTFRACTURE_TEST_DATA_DIR;
const std::string kMeshes = BTFRACTURE_MESH_DIR;

Scene sceneOf(const std::string& json) {
    return parseScene(json, "test.json", kData);
}

Eigen::Vector3d position(const btRigidBody& body) {
    const btVector3& p = body.getCenterOfMassPosition();
    return {p.x(), p.y(), p.z()};
}

// Tolerances for Bullet quantities: btScalar may be float.
const double kFloat = std::is_same<btScalar, float>::value ? 2e-6 : 1e-12;

}  // namespace

// Free fall of a sphere high above the ground, before any contact. Bullet integrates semi-implicit
// Euler (v += g h, then x += v h), so after n steps y_n = y0 - g h^2 n (n + 1) / 2 exactly; the
// analytic y0 - g t^2 / 2 differs from it by g h t / 2 (first-order time error, 10 mm here).
TEST(SceneWorld, FreeFallMatchesAnalyticBeforeContact) {
    const double h = 1.0 / 240.0, g = 9.81, y0 = 10.0;
    SceneWorld world(sceneOf(R"({"world": {"dt": 0.004166666666666667, "gravity": [0, -9.81, 0]},
        "bodies": [{"name": "ground", "shape": {"type": "plane"}},
                   {"name": "ball", "shape": {"type": "sphere", "radius": 0.1}, "position": [0, 10, 0]}]})"));
    const btRigidBody& ball = *world.bodies()[1].rigidBody;
    for (int n = 1; n <= 120; ++n) {
        world.stepFrame();
        const double t = n * h;
        const double y = position(ball).y();
        ASSERT_NEAR(y, y0 - g * h * h * n * (n + 1) / 2.0, 20 * kFloat * y0) << "step " << n;
        ASSERT_NEAR(y, y0 - g * t * t / 2.0, g * h * t / 2.0 + 20 * kFloat * y0) << "step " << n;
        ASSERT_NEAR(ball.getLinearVelocity().y(), -g * t, 20 * kFloat * g * t);
    }
    EXPECT_NEAR(world.time(), 0.5, 1e-12);
    EXPECT_NEAR(position(ball).x(), 0.0, 1e-12);  // no sideways drift
}

TEST(SceneWorld, FirstNonFiniteBodyNamesTheBodyWithNaNState) {
    SceneWorld world(sceneOf(R"({"bodies": [{"name": "ground", "shape": {"type": "plane"}},
        {"name": "a", "shape": {"type": "sphere", "radius": 0.1}, "position": [0, 1, 0]},
        {"name": "b", "shape": {"type": "sphere", "radius": 0.1}, "position": [1, 1, 0]}]})"));
    world.stepFrame();
    EXPECT_EQ(world.firstNonFiniteBody(), nullptr);
    world.bodies()[2].rigidBody->setAngularVelocity(btVector3(0, std::nan(""), 0));
    ASSERT_NE(world.firstNonFiniteBody(), nullptr);
    EXPECT_EQ(world.firstNonFiniteBody()->name, "b");
}

// A box dropped onto the ground comes to rest with its centre at its half extent. Bullet's box
// keeps its margin inside the half extents, so the only error is resting penetration, a small
// fraction of the 0.04 m contact margin: asserted to 1 mm (measured: below 1e-6 m).
TEST(SceneWorld, BoxComesToRestOnThePlaneAtItsHalfExtent) {
    SceneWorld world(sceneOf(R"({"world": {"dt": 0.004, "steps": 400},
        "bodies": [{"name": "ground", "shape": {"type": "plane"}},
                   {"name": "box", "shape": {"type": "box", "half_extents": [0.3, 0.25, 0.2]},
                    "position": [0, 1, 0], "density": 500}]})"));
    const btRigidBody& box = *world.bodies()[1].rigidBody;
    EXPECT_NEAR(1.0 / box.getInvMass(), 500 * 0.6 * 0.5 * 0.4, 60 * (1e-12 + kFloat));
    for (int n = 0; n < 400; ++n) world.stepFrame();
    EXPECT_NEAR(position(box).y(), 0.25, 0.001);
    EXPECT_LT(box.getLinearVelocity().norm(), 1e-3);
    EXPECT_LT(std::abs(box.getWorldTransform().getBasis()[1][1] - 1.0), 1e-4);  // still upright
}

// Mesh bodies: exact mass and principal inertia from the mesh, body frame at the centre of mass,
// and the output surface lands exactly where the scene put the mesh file's coordinates.
TEST(SceneWorld, MeshBodiesUseExactMassPropertiesAtTheCentreOfMass) {
    const Scene scene = parseScene(R"({"bodies": [
        {"name": "cube", "shape": {"type": "mesh", "file": "formats/cube.obj"}, "density": 100},
        {"name": "bunny", "shape": {"type": "mesh", "file": ")" +
                                       kMeshes + R"(/bunny.obj"}, "scale": [0.05, 0.04, 0.05],
         "position": [1, 2, 3], "orientation": {"axis": [1, 2, 3], "degrees": 40}, "mass": 7}]})",
                                   "test.json", kData);
    SceneWorld world(scene);
    const btRigidBody& cube = *world.bodies()[0].rigidBody;
    EXPECT_NEAR(1.0 / cube.getInvMass(), 800.0, 800 * (1e-12 + kFloat));
    const double cubeInertia = 800.0 * (4.0 + 4.0) / 12.0;  // m (a^2 + b^2) / 12, side 2
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(1.0 / cube.getInvInertiaDiagLocal()[k], cubeInertia, 1e-5 * cubeInertia);

    TriangleMesh bunny = readMesh(kMeshes + "/bunny.obj");
    for (auto& v : bunny.vertices) v = v.cwiseProduct(Eigen::Vector3d(0.05, 0.04, 0.05));
    const MassProperties mass = computeMassProperties(bunny);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(40 * M_PI / 180, Eigen::Vector3d(1, 2, 3).normalized()));
    const Eigen::Vector3d p(1, 2, 3);
    const btRigidBody& body = *world.bodies()[1].rigidBody;
    EXPECT_NEAR(1.0 / body.getInvMass(), 7.0, 1e-12 * 7 + kFloat * 7);
    EXPECT_LT((position(body) - (p + q * mass.centreOfMass)).norm(), 10 * kFloat);
    const PrincipalAxes axes = principalAxes(mass.inertiaPerDensity * (7.0 / mass.volume));
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(1.0 / body.getInvInertiaDiagLocal()[k], axes.moments[k], 1e-5 * axes.moments[k]);
    // Output surface = the file's vertices, scaled, rotated and moved as the scene says.
    const TriangleMesh surface = world.worldSurface(1);
    ASSERT_EQ(surface.vertices.size(), bunny.vertices.size());
    double worst = 0.0;
    for (size_t i = 0; i < bunny.vertices.size(); ++i)
        worst = std::max(worst, (surface.vertices[i] - (p + q * bunny.vertices[i])).norm());
    EXPECT_LT(worst, 20 * kFloat);
    EXPECT_EQ(surface.triangles, bunny.triangles);
}

// The same cube mesh as a shrunk convex hull and as GImpact (moved in by its 0.04 m margin): both
// rest on the ground at the cube's half side (1 m) to 1 mm (measured 0.06 and 0.03 mm).
TEST(SceneWorld, MeshCollisionShapesRestOnTheGround) {
    for (const char* collision : {"convex_hull", "gimpact"}) {
        SCOPED_TRACE(collision);
        SceneWorld world(sceneOf(
            std::string(R"({"world": {"dt": 0.004}, "bodies": [{"name": "ground", "shape": {"type": "plane"}},
            {"name": "cube", "shape": {"type": "mesh", "file": "formats/cube.obj", "collision": ")") +
            collision + R"("}, "position": [0, 1.5, 0], "density": 100}]})"));
        const btRigidBody& cube = *world.bodies()[1].rigidBody;
        for (int n = 0; n < 500; ++n) world.stepFrame();
        const double y = position(cube).y();
        EXPECT_NEAR(y, 1.0, 0.001);
        EXPECT_LT(cube.getLinearVelocity().norm(), 1e-2);
    }
}

TEST(SceneWorld, PrimitiveSurfacesAreClosedSolids) {
    SceneWorld world(sceneOf(
        R"({"bodies": [{"name": "ground", "shape": {"type": "plane", "normal": [0, 0, 1], "offset": -2}},
        {"name": "box", "shape": {"type": "box", "half_extents": [1, 2, 3]}, "scale": [2, 1, 1]},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "scale": 2}]})"));
    const auto& bodies = world.bodies();
    for (size_t i = 1; i < 3; ++i) {
        const MeshDefects d = inspectMesh(bodies[i].surface);
        EXPECT_TRUE(d.isClosedSolid()) << bodies[i].name << ": " << d.describe();
        EXPECT_GT(d.signedVolume, 0.0);
    }
    EXPECT_DOUBLE_EQ(bodies[1].volume, 8 * 2 * 2 * 3);
    EXPECT_NEAR(computeMassProperties(bodies[1].surface).volume, bodies[1].volume, 1e-12);
    EXPECT_NEAR(bodies[2].volume, 4.0 / 3.0 * M_PI, 1e-12);
    EXPECT_NEAR(computeMassProperties(bodies[2].surface).volume, bodies[2].volume, 0.02 * bodies[2].volume);
    // The plane's display square lies in the plane z = -2 and faces +z.
    for (const auto& v : bodies[0].surface.vertices) EXPECT_DOUBLE_EQ(v.z(), -2.0);
    const Eigen::Vector3d n = (bodies[0].surface.vertices[1] - bodies[0].surface.vertices[0])
                                  .cross(bodies[0].surface.vertices[2] - bodies[0].surface.vertices[0]);
    EXPECT_GT(n.z(), 0.0);
}

// The factory is the single place where the world and the bodies are created.
TEST(SceneWorld, FactoryCreatesWorldAndBodies) {
    struct TaggedBody : btRigidBody {
        TaggedBody(const btRigidBodyConstructionInfo& info, std::string tag)
            : btRigidBody(info), tag(std::move(tag)) {}
        std::string tag;
    };
    struct CountingFactory : SceneWorldFactory {
        mutable int worlds = 0, bodies = 0;
        mutable size_t surfaceVertices = 0;
        std::unique_ptr<btDiscreteDynamicsWorld> createWorld(btCollisionDispatcher& d,
                                                             btBroadphaseInterface& b, btConstraintSolver& s,
                                                             btCollisionConfiguration& c,
                                                             const Scene& scene) const override {
            ++worlds;
            return SceneWorldFactory::createWorld(d, b, s, c, scene);
        }
        std::unique_ptr<btRigidBody> createBody(const btRigidBody::btRigidBodyConstructionInfo& info,
                                                const SceneBody& description,
                                                const TriangleMesh& surface) const override {
            ++bodies;
            surfaceVertices += surface.vertices.size();
            return std::make_unique<TaggedBody>(
                info, description.name + (description.fracture.fracturable ? "*" : ""));
        }
    } factory;
    SceneWorld world(sceneOf(R"({"bodies": [{"name": "ground", "shape": {"type": "plane"}},
        {"name": "cube", "shape": {"type": "mesh", "file": "formats/cube.obj"}, "position": [0, 3, 0]}],
        "effects": {"fracture": {"cube": true}}})"),
                     factory);
    EXPECT_EQ(factory.worlds, 1);
    EXPECT_EQ(factory.bodies, 2);
    EXPECT_EQ(factory.surfaceVertices, 4u + 8u);
    ASSERT_EQ(world.world().getNumCollisionObjects(), 2);
    EXPECT_EQ(dynamic_cast<TaggedBody&>(*world.bodies()[1].rigidBody).tag, "cube*");
    EXPECT_EQ(world.world().getCollisionObjectArray()[1], world.bodies()[1].rigidBody);
    world.stepFrame();
    EXPECT_LT(position(*world.bodies()[1].rigidBody).y(), 3.0);
}

TEST(SceneWorld, BadMeshNamesSceneBodyAndDefect) {
    try {
        SceneWorld world(sceneOf(
            R"({"bodies": [{"name": "lid", "shape": {"type": "mesh", "file": "bad_meshes/open.obj"}}]})"));
        FAIL() << "open mesh accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("test.json: body 'lid': " + kData + "/bad_meshes/open.obj: not a closed"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("3 boundary edges"), std::string::npos) << message;
    }
}

// A kinematic body moves at exactly its scene velocity, ignores gravity, and pushes a dynamic box
// it runs into; a sleeping body hangs in the air until something wakes it. Friction and
// restitution reach Bullet.
TEST(SceneWorld, KinematicSleepingFrictionRestitution) {
    SceneWorld world(sceneOf(R"({"world": {"dt": 0.01, "gravity": [0, -9.81, 0]},
        "bodies": [{"name": "ground", "shape": {"type": "plane"}, "friction": 0.9},
                   {"name": "pusher", "shape": {"type": "box", "half_extents": [0.1, 0.1, 0.1]},
                    "position": [-1, 0.1, 0], "state": "kinematic", "linear_velocity": [2, 0, 0],
                    "angular_velocity": [0, 1, 0]},
                   {"name": "crate", "shape": {"type": "box", "half_extents": [0.1, 0.1, 0.1]},
                    "position": [0, 0.1, 0], "restitution": 0.3},
                   {"name": "lamp", "shape": {"type": "sphere", "radius": 0.1}, "position": [5, 3, 0],
                    "state": "sleeping"}]})"));
    const btRigidBody& pusher = *world.bodies()[1].rigidBody;
    const btRigidBody& crate = *world.bodies()[2].rigidBody;
    const btRigidBody& lamp = *world.bodies()[3].rigidBody;
    EXPECT_TRUE(pusher.isKinematicObject());
    EXPECT_FLOAT_EQ(world.bodies()[0].rigidBody->getFriction(), 0.9f);
    EXPECT_FLOAT_EQ(crate.getRestitution(), 0.3f);
    for (int n = 1; n <= 100; ++n) {
        world.stepFrame();
        ASSERT_NEAR(position(pusher).x(), -1.0 + 2.0 * 0.01 * n, 1e-4) << "step " << n;
        ASSERT_NEAR(position(pusher).y(), 0.1, 1e-6) << "step " << n;
    }
    // The yaw advanced by w t = 1 rad.
    const btQuaternion q = pusher.getWorldTransform().getRotation();
    EXPECT_NEAR(q.getAngle(), 1.0, 1e-3);
    // The pusher reached x = 1 at t = 1 s, so the crate (at x = 0, 0.2 m wide) was pushed along.
    EXPECT_GT(position(crate).x(), 0.5);
    EXPECT_NEAR(position(lamp).y(), 3.0, 1e-12);
    EXPECT_EQ(lamp.getActivationState(), ISLAND_SLEEPING);
}

// The scene's engine-wide effects reach the fracture engine and world the factory makes.
TEST(SceneWorld, FractureFactoryPassesTheEngineEffects) {
    const auto engineOf = [](SceneWorld& world) {
        const auto* fractureWorld = dynamic_cast<const btFractureDynamicsWorld*>(&world.world());
        return fractureWorld ? dynamic_cast<const BemFractureEngine*>(fractureWorld->fractureEngine())
                             : nullptr;
    };
    const std::string bodies = R"("bodies": [{"name": "ground", "shape": {"type": "plane"}},
        {"name": "slab", "shape": {"type": "box", "half_extents": [0.1, 0.02, 0.1]}, "position": [0, 0.02, 0],
         "material": "glass"}])";
    const FractureSceneWorldFactory factory(0);
    SceneWorld plain(sceneOf("{" + bodies + R"(, "effects": {"fracture": {"slab": true}}})"), factory);
    SceneWorld set(
        sceneOf(
            "{" + bodies +
            R"(, "effects": {"surface_seeds": true, "estimator_surface_fronts": true, "idle_matrix_budget_mb": 0,
                                                  "crack_cut": "coarse_sheet", "fragment_sleeping": true,
                                                  "fracture": {"slab": true}}})"),
        factory);
    ASSERT_NE(engineOf(plain), nullptr);
    ASSERT_NE(engineOf(set), nullptr);
    const BemFractureEngineSettings defaults;
    EXPECT_EQ(engineOf(plain)->settings().fracture.surfaceSeeds, defaults.fracture.surfaceSeeds);
    EXPECT_EQ(engineOf(plain)->settings().fracture.estimatorSurfaceFronts,
              defaults.fracture.estimatorSurfaceFronts);
    EXPECT_EQ(engineOf(plain)->settings().idleMatrixBudgetMB, defaults.idleMatrixBudgetMB);
    EXPECT_TRUE(engineOf(set)->settings().fracture.surfaceSeeds);
    EXPECT_TRUE(engineOf(set)->settings().fracture.estimatorSurfaceFronts);
    EXPECT_EQ(engineOf(set)->settings().idleMatrixBudgetMB, 0.0);
    EXPECT_FALSE(engineOf(set)->settings().voxelFronts);
    const auto sleepingOf = [](SceneWorld& world) {
        return dynamic_cast<const btFractureDynamicsWorld&>(world.world()).fragmentSleepingEnabled();
    };
    EXPECT_FALSE(sleepingOf(plain));
    EXPECT_TRUE(sleepingOf(set));
}
