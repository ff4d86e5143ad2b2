// SPDX-License-Identifier: Zlib
// ContactIslandManager (fragment sleeping on): a settled body sleeps next to a body that keeps
// moving without touching it, which Bullet's islands (joined by overlapping broadphase leaves)
// do not allow, and a body that comes to touch it wakes it.
#include <btFracture/dynamics/ContactIslandManager.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <gtest/gtest.h>

#include <memory>

using namespace btfracture;

namespace {

// A 10 cm box resting on the ground and, 3 cm above it (their broadphase leaves overlap), a 5 cm
// ball that hovers (no gravity) spinning at 5 rad/s: it never falls under Bullet's sleeping
// thresholds.
struct BoxUnderSpinningBall {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btFractureDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
    btStaticPlaneShape plane{btVector3(0, 1, 0), 0};
    btBoxShape cube{btVector3(0.05f, 0.05f, 0.05f)};
    btSphereShape sphere{0.05f};
    std::unique_ptr<btRigidBody> ground, box, ball;

    explicit BoxUnderSpinningBall(bool fragmentSleeping) {
        world.setGravity(btVector3(0, -9.81f, 0));
        world.setFragmentSleeping(fragmentSleeping);
        ground = makeBody(plane, 0, btVector3(0, 0, 0));
        box = makeBody(cube, 1, btVector3(0, 0.05f, 0));
        ball = makeBody(sphere, 0.5f, btVector3(0, 0.23f, 0));
        ball->setGravity(btVector3(0, 0, 0));
        ball->setAngularVelocity(btVector3(0, 5, 0));
    }
    ~BoxUnderSpinningBall() {
        for (auto* body : {ball.get(), box.get(), ground.get()}) world.removeRigidBody(body);
    }
    std::unique_ptr<btRigidBody> makeBody(btCollisionShape& shape, btScalar mass, const btVector3& at) {
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape.calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &shape, inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(at);
        auto body = std::make_unique<btRigidBody>(info);
        world.addRigidBody(body.get());
        return body;
    }
    void run(double seconds) {
        for (int s = 0; s < int(seconds * 240 + 0.5); ++s) world.stepSimulation(btScalar(1.0 / 240), 0);
    }
};

}  // namespace

TEST(ContactIslands, SettledBodySleepsNextToAMovingOneAndWakesWhenTouched) {
    BoxUnderSpinningBall bullet(false), contact(true);
    bullet.run(2.5);  // past Bullet's 2 s deactivation time
    contact.run(2.5);
    // Bullet's islands: the box shares one with the spinning ball and stays awake.
    EXPECT_TRUE(bullet.box->isActive());
    EXPECT_EQ(bullet.box->getIslandTag(), bullet.ball->getIslandTag());
    // Islands of touching bodies: the box has its own and sleeps; the ball spins on.
    EXPECT_EQ(contact.box->getActivationState(), ISLAND_SLEEPING);
    EXPECT_TRUE(contact.ball->isActive());
    EXPECT_NE(contact.box->getIslandTag(), contact.ball->getIslandTag());
    EXPECT_LT(double(contact.box->getWorldTransform().getOrigin().y()), 0.0505);
    // The ball falls onto the box: the contact joins their islands and wakes the box.
    contact.ball->setGravity(btVector3(0, -9.81f, 0));
    contact.run(0.3);
    EXPECT_TRUE(contact.box->isActive());
    EXPECT_EQ(contact.box->getIslandTag(), contact.ball->getIslandTag());
    // Off again: Bullet's island manager is back.
    EXPECT_NE(dynamic_cast<ContactIslandManager*>(contact.world.getSimulationIslandManager()), nullptr);
    contact.world.setFragmentSleeping(false);
    EXPECT_EQ(dynamic_cast<ContactIslandManager*>(contact.world.getSimulationIslandManager()), nullptr);
    contact.run(0.1);
}
