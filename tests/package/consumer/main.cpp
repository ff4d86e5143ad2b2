// SPDX-License-Identifier: Zlib
// Consumer of the installed btFracture package: plain Bullet world, a btfracture::Material, and
// a btFracture scene world (Bullet types crossing the library boundary), in the package's
// Bullet precision.
#include <btBulletDynamicsCommon.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Material.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <cmath>
#include <cstdio>

static_assert(sizeof(btScalar) == (PACKAGE_BULLET_DOUBLE ? 8 : 4),
              "btScalar does not match the package's precision");

int fail(const char* what) {
    std::fprintf(stderr, "consumer: FAILED: %s\n", what);
    return 1;
}

int main() {
    if (PACKAGE_BULLET_DOUBLE != EXPECT_BULLET_DOUBLE)
        return fail("package reports the wrong Bullet precision");

    // An ordinary Bullet app: a ball falls 0.5 s onto nothing.
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, -10, 0));
    btSphereShape sphere(0.5);
    btVector3 inertia;
    sphere.calculateLocalInertia(1, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &sphere, inertia);
    info.m_startWorldTransform.setOrigin(btVector3(0, 10, 0));
    btRigidBody ball(info);
    world.addRigidBody(&ball);
    for (int i = 0; i < 50; ++i) world.stepSimulation(btScalar(0.01), 0);
    const double y = ball.getCenterOfMassPosition().y();
    world.removeRigidBody(&ball);
    if (!(std::abs(y - (10 - 0.5 * 10 * 0.01 * 0.01 * 50 * 51)) < 1e-3)) return fail("Bullet free fall");

    // btFracture's own types.
    const btfracture::Material pmma = btfracture::Material::pmma();
    if (pmma.youngsModulus() != 3.1e9) return fail("Material::pmma");
    try {
        btfracture::Material bad(-1, 0.3, 1000, 1e6, 1e5, 2);
        return fail("a negative Young's modulus was accepted");
    } catch (const btfracture::Error&) {
    }

    // A scene world built inside the library and stepped here: a box comes to rest on a plane.
    btfracture::SceneWorld scene(btfracture::parseScene(
        R"({"world": {"dt": 0.004}, "bodies": [{"name": "ground", "shape": {"type": "plane"}},
            {"name": "box", "shape": {"type": "box", "half_extents": [0.25, 0.25, 0.25]}, "position": [0, 1, 0]}]})",
        "consumer.json", "."));
    for (int i = 0; i < 300; ++i) scene.stepFrame();
    const double rest = scene.bodies()[1].rigidBody->getCenterOfMassPosition().y();
    if (!(std::abs(rest - 0.25) < 1e-3)) return fail("box resting on the plane");

    std::printf("consumer OK: btScalar has %d bytes, box rests at %.4f m\n",
                static_cast<int>(sizeof(btScalar)), rest);
    return 0;
}
