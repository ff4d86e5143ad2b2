// SPDX-License-Identifier: Zlib
// Consumer of the installed btFracture package, as an application uses it: one header, the
// package's Bullet precision, a plain Bullet world, a btfracture::Material, and a glass slab that
// a steel ball breaks in a btFractureDynamicsWorld with the physical engine.
#include <btFracture/btFracture.h>

#include <cmath>
#include <cstdio>
#include <memory>

static_assert(sizeof(btScalar) == (PACKAGE_BULLET_DOUBLE ? 8 : 4),
              "btScalar does not match the package's precision");

namespace {

int fail(const char* what) {
    std::fprintf(stderr, "consumer: FAILED: %s\n", what);
    return 1;
}

struct Fragments : btfracture::FractureListener {
    double parentMass = 0.0, fragmentMass = 0.0;
    void onFractureEvent(btfracture::btFractureRigidBody& parent,
                         const std::vector<btfracture::btFractureRigidBody*>& fragments,
                         const btfracture::FractureEventInfo&) override {
        if (parentMass > 0.0) return;  // the slab's event
        parentMass = 1.0 / parent.getInvMass();
        for (const auto* f : fragments) fragmentMass += 1.0 / f->getInvMass();
    }
};

}  // namespace

int main() {
    if (PACKAGE_BULLET_DOUBLE != EXPECT_BULLET_DOUBLE)
        return fail("package reports the wrong Bullet precision");

    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    {
        // An ordinary Bullet app: a ball falls 0.5 s onto nothing.
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
    }

    // btFracture's types and their validation.
    const btfracture::Material pmma = btfracture::Material::pmma();
    if (pmma.youngsModulus() != 3.1e9) return fail("Material::pmma");
    try {
        btfracture::Material bad(-1, 0.3, 1000, 1e6, 1e5, 2);
        return fail("a negative Young's modulus was accepted");
    } catch (const btfracture::Error&) {
    }

    // A fracture world: a 4.1 kg steel ball at 25 m/s breaks a glass slab.
    btfracture::btFractureDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, -9.81f, 0));
    world.setFractureEngine(std::make_unique<btfracture::BemFractureEngine>());
    Fragments fragments;
    world.addFractureListener(&fragments);
    btBoxShape groundShape(btVector3(5, 0.5f, 5));
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
    ground.getWorldTransform().setOrigin(btVector3(0, -0.5f, 0));
    world.addRigidBody(&ground);
    btfracture::FractureBodySettings settings;
    settings.impulseThreshold = 10;  // [N s]
    settings.bemTriangleTarget = 600;
    btTransform pose(btQuaternion::getIdentity(), btVector3(0, 0.025f, 0));
    btfracture::btFractureRigidBody slab(btfracture::Material::glass(),
                                         btBoxShape(btVector3(0.2f, 0.025f, 0.2f)), settings, pose);
    world.addRigidBody(&slab);
    btSphereShape ballShape(0.05f);
    btVector3 ballInertia;
    ballShape.calculateLocalInertia(4.1f, ballInertia);
    btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(4.1f, nullptr, &ballShape, ballInertia));
    ball.getWorldTransform().setOrigin(btVector3(0.05f, 0.2f, 0.03f));
    ball.setLinearVelocity(btVector3(0, -25, 0));
    world.addRigidBody(&ball);
    for (int step = 0; step < 60 && fragments.parentMass == 0.0; ++step)
        world.stepSimulation(1.0f / 240, 1, 1.0f / 240);
    const btfracture::FractureStatistics& stats = world.fractureStatistics();
    if (stats.fractureEvents < 1) return fail("the glass slab did not break");
    if (!(std::abs(fragments.fragmentMass / fragments.parentMass - 1.0) < 0.03))
        return fail("the fragments do not carry the slab's mass (3 %)");
    for (btRigidBody* body : {&ball, static_cast<btRigidBody*>(&slab), &ground})
        if (body->isInWorld()) world.removeRigidBody(body);

    std::printf(
        "consumer OK: btScalar has %d bytes, the slab broke into %llu fragments (mass %.4f of %.4f kg)\n",
        static_cast<int>(sizeof(btScalar)), static_cast<unsigned long long>(stats.fragmentsSpawned),
        fragments.fragmentMass, fragments.parentMass);
    return 0;
}
