// SPDX-License-Identifier: Zlib
// Fragments spin no faster than Bullet turns them in a step (dynamics/SpinLimit.h).
#include "../support/GroundCheck.h"
#include "CouplingScene.h"

#include <btFracture/dynamics/SpinLimit.h>

#include <LinearMath/btTransformUtil.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace btfracture;
using namespace btfracture::test;

namespace {

// A 14 x 2 x 1.2 mm sliver of 70 mg thrown at the ground at 4.6 m/s, spinning at
// 1,500 rad/s about a seeded axis (what a chase ball gave a chip in the stability suite); 2 s
// at 240 Hz in Bullet's own world, its solver set as btFractureDynamicsWorld sets it for
// fragments (split impulse below 0.5 mm). Returns the top of its bounding box at the end [m].
double sliverTopAtEnd(int seed, bool limitSpin) {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, btScalar(-9.81), 0));
    world.getSolverInfo().m_splitImpulsePenetrationThreshold = btScalar(-0.0005);
    btStaticPlaneShape plane(btVector3(0, 1, 0), 0);
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &plane));
    world.addRigidBody(&ground);

    const double a = 0.007, b = 0.001, c = 0.0006, mass = 7e-5;
    btConvexHullShape hull;
    for (int i = 0; i < 8; ++i)
        hull.addPoint(
            btVector3(btScalar(i & 1 ? a : -a), btScalar(i & 2 ? b : -b), btScalar(i & 4 ? c : -c)));
    hull.setMargin(btScalar(0.00012));
    hull.recalcLocalAabb();
    const btVector3 inertia(btScalar(mass * (b * b + c * c) / 3), btScalar(mass * (a * a + c * c) / 3),
                            btScalar(mass * (a * a + b * b) / 3));
    btRigidBody sliver(btRigidBody::btRigidBodyConstructionInfo(btScalar(mass), nullptr, &hull, inertia));
    sliver.setWorldTransform(btTransform(btQuaternion(btVector3(1, 2, 3).normalized(), btScalar(0.1 * seed)),
                                         btVector3(0, btScalar(0.02), 0)));
    world.addRigidBody(&sliver);
    // Golden-angle axes: seeded, spread over the sphere.
    const double z = 1.0 - 2.0 * (seed + 0.5) / 200.0, phi = 2.39996323 * seed, r = std::sqrt(1.0 - z * z);
    sliver.setLinearVelocity(btVector3(btScalar(-0.4), btScalar(-3.3), btScalar(3.2)));
    sliver.setAngularVelocity(
        btVector3(btScalar(r * std::cos(phi)), btScalar(r * std::sin(phi)), btScalar(z)) * btScalar(1500.0));
    for (int s = 0; s < 480; ++s) {
        if (limitSpin) limitSpinToStep(sliver, kStep);
        world.stepSimulation(btScalar(kStep), 1, btScalar(kStep));
    }
    btVector3 lo, hi;
    sliver.getAabb(lo, hi);
    world.removeRigidBody(&sliver);
    world.removeRigidBody(&ground);
    return double(hi.y());
}

}  // namespace

TEST(SpinLimit, CutsToWhatAStepTurnsAndKeepsTheAxis) {
    EXPECT_NEAR(integrableSpin(kStep), M_PI / 4.0 / kStep, 1e-4);  // 188.5 rad/s at 240 Hz (float pi)
    btSphereShape shape(1);
    btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(1, nullptr, &shape, btVector3(1, 1, 1)));
    const btVector3 fast(300, -400, 0);  // 500 rad/s
    body.setAngularVelocity(fast);
    EXPECT_NEAR(limitSpinToStep(body, kStep), 500.0, 1e-4);
    EXPECT_NEAR(double(body.getAngularVelocity().length()), integrableSpin(kStep), 1e-3);
    EXPECT_NEAR(double(body.getAngularVelocity().normalized().dot(fast.normalized())), 1.0, 1e-6);
    const btVector3 slow(10, 0, 0);
    body.setAngularVelocity(slow);
    EXPECT_EQ(limitSpinToStep(body, kStep), 0.0);
    EXPECT_EQ(body.getAngularVelocity(), slow);
}

// Bullet turns a body by at most pi/4 per step but its contact solver uses the whole spin: such
// slivers sink through the ground plane. With the spin limited none ends below it.
TEST(SpinLimit, SpinningSliversStayAboveTheGround) {
    constexpr int kThrows = 200;
    int belowPlain = 0, belowLimited = 0;
    double lowestLimited = INFINITY;
    for (int seed = 0; seed < kThrows; ++seed) {
        belowPlain += sliverTopAtEnd(seed, false) < -kGroundSlop;
        const double top = sliverTopAtEnd(seed, true);
        belowLimited += top < -kGroundSlop;
        lowestLimited = std::min(lowestLimited, top);
    }
    std::printf(
        "slivers wholly below the ground after 2 s: %d of %d with Bullet's spin, %d with the limit "
        "(lowest top %.4f m)\n",
        belowPlain, kThrows, belowLimited, lowestLimited);
    EXPECT_GE(belowPlain, 5) << "the throw no longer shows Bullet's spin problem";
    EXPECT_EQ(belowLimited, 0);
}

// The world limits its fragments' spin before it integrates them, and counts it; bodies the
// application added keep theirs.
TEST(SpinLimit, WorldLimitsFragmentsOnly) {
    SceneOptions options;
    options.maxRefractureDepth = 0;  // fragments (depth 1) do not break again
    Scene scene(options);
    for (int i = 0; i < 10 && scene.fragments().empty(); ++i) scene.step();
    const auto fragments = scene.fragments();
    ASSERT_FALSE(fragments.empty());
    const double limit = integrableSpin(kStep);
    fragments.front()->setAngularVelocity(btVector3(btScalar(5.0 * limit), 0, 0));
    scene.ball->setAngularVelocity(btVector3(0, btScalar(3.0 * limit), 0));
    const std::uint64_t before = scene.world->fractureStatistics().spinsLimited;
    scene.step();
    ASSERT_TRUE(fragments.front()->isInWorld());
    EXPECT_LE(double(fragments.front()->getAngularVelocity().length()), limit * (1.0 + 1e-6));
    EXPECT_EQ(scene.world->fractureStatistics().spinsLimited, before + 1);
    EXPECT_GT(double(scene.ball->getAngularVelocity().length()), 2.0 * limit);
}
