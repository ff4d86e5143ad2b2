// SPDX-License-Identifier: Zlib
// The shortest complete program that adds btFracture to an ordinary Bullet app: a world, a
// ground, one breakable glass slab and a steel ball thrown at it. Compared with plain Bullet it
// includes one header and changes three things, marked (1) (2) (3).
//
// (2) is the physical engine (BEM stress, cracks, level-set fragments); tests use a plane-split
// stand-in through the same one line.
//
// Exit status: 0 when the slab broke, 1 otherwise (it runs as the CTest test coupling.minimal_app).
#include <btFracture/btFracture.h>  // with Bullet's btBulletDynamicsCommon.h

#include <cstdio>
#include <memory>

using namespace btfracture;

int main() {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    // (1) instead of btDiscreteDynamicsWorld
    btFractureDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, -9.81f, 0));
    // (2) who decides how things break
    world.setFractureEngine(std::make_unique<BemFractureEngine>());

    btBoxShape groundShape(btVector3(5, 0.5f, 5));
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
    ground.getWorldTransform().setOrigin(btVector3(0, -0.5f, 0));
    world.addRigidBody(&ground);

    // (3) a breakable body: material, shape, settings, pose
    FractureBodySettings settings;
    settings.impulseThreshold = 10;  // [N s]
    btTransform pose(btQuaternion::getIdentity(), btVector3(0, 0.025f, 0));
    btFractureRigidBody slab(Material::glass(), btBoxShape(btVector3(0.2f, 0.025f, 0.2f)), settings, pose);
    world.addRigidBody(&slab);

    btSphereShape ballShape(0.05f);
    btVector3 ballInertia;
    ballShape.calculateLocalInertia(4.1f, ballInertia);
    btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(4.1f, nullptr, &ballShape, ballInertia));
    ball.getWorldTransform().setOrigin(btVector3(0.05f, 0.2f, 0.03f));
    ball.setLinearVelocity(btVector3(0, -10, 0));
    world.addRigidBody(&ball);

    for (int step = 0; step < 120; ++step) world.stepSimulation(1.0f / 240, 1, 1.0f / 240);

    const FractureStatistics& stats = world.fractureStatistics();
    std::printf("fracture events: %llu, fragments: %llu, slab still in the world: %s\n",
                static_cast<unsigned long long>(stats.fractureEvents),
                static_cast<unsigned long long>(stats.fragmentsSpawned), slab.isInWorld() ? "yes" : "no");

    // Clean-up: fragments belong to the world and go with it; the app's own bodies leave first.
    for (btRigidBody* body : {&ball, static_cast<btRigidBody*>(&slab), &ground})
        if (body->isInWorld()) world.removeRigidBody(body);
    return stats.fractureEvents > 0 ? 0 : 1;
}
