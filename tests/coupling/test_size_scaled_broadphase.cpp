// SPDX-License-Identifier: Zlib
// SizeScaledBroadphase: every leaf holds its body's box (no pair within the contact breaking
// threshold is lost), a chip's leaf is widened by the fraction of its size instead of Bullet's
// 5 cm, a metre-sized body keeps Bullet's margin, and a heap of chips makes far fewer pairs.
#include <btFracture/dynamics/SizeScaledBroadphase.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "../support/BroadphaseBoxes.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

using namespace btfracture;
using btfracture::test::boxesOverlap;

namespace {

// No gravity; an n x n x n lattice of cubes (edge `edge`, `spacing` apart) drifting without
// turning at up to `speed` in seeded random directions, 250 Hz.
struct Drift {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    std::unique_ptr<btDbvtBroadphase> broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::unique_ptr<btDiscreteDynamicsWorld> world;
    btBoxShape cube;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    Drift(std::unique_ptr<btDbvtBroadphase> bp, int n, btScalar edge, btScalar spacing, btScalar speed)
        : broadphase(std::move(bp)), cube(btVector3(edge, edge, edge) / 2) {
        world = std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, broadphase.get(), &solver, &config);
        world->setGravity(btVector3(0, 0, 0));
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        btVector3 inertia;
        cube.calculateLocalInertia(1, inertia);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    btTransform pose(btQuaternion::getIdentity(), btVector3(i, j, k) * spacing);
                    auto body = std::make_unique<btRigidBody>(
                        btRigidBody::btRigidBodyConstructionInfo(1, nullptr, &cube, inertia));
                    body->setWorldTransform(pose);
                    body->setLinearVelocity(btVector3(unit(random), unit(random), unit(random)) * speed);
                    body->setAngularFactor(0);  // boxes of constant size
                    body->setActivationState(DISABLE_DEACTIVATION);
                    world->addRigidBody(body.get());
                    bodies.push_back(std::move(body));
                }
    }
    void step() { world->stepSimulation(btScalar(0.004), 0); }
    // The broadphase brought up to the current poses, as at the start of Bullet's next step.
    void refresh() {
        world->updateAabbs();
        broadphase->calculateOverlappingPairs(&dispatcher);
    }
};

btVector3 leafMin(const btRigidBody& b) {
    return static_cast<const btDbvtProxy*>(b.getBroadphaseHandle())->leaf->volume.Mins();
}
btVector3 leafMax(const btRigidBody& b) {
    return static_cast<const btDbvtProxy*>(b.getBroadphaseHandle())->leaf->volume.Maxs();
}

// Steps both drifts and asserts every leaf of `scaled` to be that of `bullet`, bit for bit.
void assertBulletsLeaves(Drift& bullet, Drift& scaled, int steps) {
    for (int s = 0; s < steps; ++s) {
        bullet.step();
        scaled.step();
        for (std::size_t i = 0; i < bullet.bodies.size(); ++i) {
            ASSERT_EQ(leafMin(*bullet.bodies[i]), leafMin(*scaled.bodies[i]))
                << "body " << i << " at step " << s;
            ASSERT_EQ(leafMax(*bullet.bodies[i]), leafMax(*scaled.bodies[i]))
                << "body " << i << " at step " << s;
        }
    }
}

long long pairsOver(Drift& drift, int steps) {
    long long pairs = 0;
    for (int s = 0; s < steps; ++s) {
        drift.step();
        pairs += drift.broadphase->getOverlappingPairCache()->getNumOverlappingPairs();
    }
    return pairs;
}

}  // namespace

TEST(SizeScaledBroadphase, LeavesHoldTheBoxAndNoOverlappingPairIsLost) {
    // 1 cm chips 2.5 cm apart at up to 1 m/s: the boxes (widened by the 2 cm contact breaking
    // threshold) overlap and separate all the time; leaves are widened by 2.5 mm.
    const btScalar edge = btScalar(0.01);
    Drift drift(std::make_unique<SizeScaledBroadphase>(btScalar(0.25)), 4, edge, btScalar(0.025), 1);
    const btScalar tolerance = btScalar(1e-6);  // [m], float rounding of 10 cm coordinates
    long long overlapping = 0;
    for (int s = 0; s < 100; ++s) {
        drift.step();
        drift.refresh();
        for (const auto& body : drift.bodies) {
            btVector3 boxMin, boxMax;
            body->getCollisionShape()->getAabb(body->getWorldTransform(), boxMin, boxMax);
            const btVector3 threshold(gContactBreakingThreshold, gContactBreakingThreshold,
                                      gContactBreakingThreshold);
            const btBroadphaseProxy& proxy = *body->getBroadphaseHandle();
            ASSERT_LT((proxy.m_aabbMin - (boxMin - threshold)).length(), tolerance) << "step " << s;
            ASSERT_LT((proxy.m_aabbMax - (boxMax + threshold)).length(), tolerance) << "step " << s;
            for (int k = 0; k < 3; ++k) {
                ASSERT_LE(leafMin(*body)[k], proxy.m_aabbMin[k]) << "step " << s;
                ASSERT_GE(leafMax(*body)[k], proxy.m_aabbMax[k]) << "step " << s;
                // The leaf is the box of an earlier step (the chip, the threshold and the step's
                // motion, at most 4 mm) widened by 0.25 of the chip and motion on each side.
                const btScalar motion = btScalar(0.004);
                ASSERT_LE(leafMax(*body)[k] - leafMin(*body)[k],
                          edge + 2 * gContactBreakingThreshold + motion +
                              2 * btScalar(0.25) * (edge + motion) + tolerance)
                    << "step " << s;
            }
        }
        btOverlappingPairCache& cache = *drift.broadphase->getOverlappingPairCache();
        for (std::size_t i = 0; i < drift.bodies.size(); ++i)
            for (std::size_t j = i + 1; j < drift.bodies.size(); ++j) {
                btBroadphaseProxy* a = drift.bodies[i]->getBroadphaseHandle();
                btBroadphaseProxy* b = drift.bodies[j]->getBroadphaseHandle();
                if (!boxesOverlap(*a, *b)) continue;
                ++overlapping;
                ASSERT_NE(cache.findPair(a, b), nullptr) << "bodies " << i << ", " << j << " at step " << s;
            }
    }
    EXPECT_GT(overlapping, 1000);  // the check above was exercised
}

TEST(SizeScaledBroadphase, MetreSizedBodiesKeepBulletsLeaves) {
    // 0.4 m cubes: 0.25 of their size exceeds gDbvtMargin, so the leaves are Bullet's, bit for bit.
    Drift bullet(std::make_unique<btDbvtBroadphase>(), 3, btScalar(0.4), 1, 5);
    Drift scaled(std::make_unique<SizeScaledBroadphase>(btScalar(0.25)), 3, btScalar(0.4), 1, 5);
    ASSERT_NO_FATAL_FAILURE(assertBulletsLeaves(bullet, scaled, 50));
    // The leaves were updated with the margin: wider than the boxes.
    const btRigidBody& body = *scaled.bodies.front();
    EXPECT_GT(
        leafMax(body).x() - leafMin(body).x(),
        body.getBroadphaseHandle()->m_aabbMax.x() - body.getBroadphaseHandle()->m_aabbMin.x() + gDbvtMargin);
}

TEST(SizeScaledBroadphase, InfiniteFractionKeepsBulletsLeavesThenScales) {
    // Chips with an infinite fraction: Bullet's leaves, bit for bit; a finite one set later
    // narrows the leaves widened from then on (at up to 3 m/s every chip leaves its 5 cm leaf
    // within the 30 steps after).
    Drift bullet(std::make_unique<btDbvtBroadphase>(), 3, btScalar(0.01), btScalar(0.03), 3);
    auto owned = std::make_unique<SizeScaledBroadphase>(std::numeric_limits<btScalar>::infinity());
    SizeScaledBroadphase& broadphase = *owned;
    Drift scaled(std::move(owned), 3, btScalar(0.01), btScalar(0.03), 3);
    ASSERT_NO_FATAL_FAILURE(assertBulletsLeaves(bullet, scaled, 30));
    broadphase.setFraction(btScalar(0.25));
    for (int s = 0; s < 30; ++s) scaled.step();
    for (const auto& body : scaled.bodies) {
        const btBroadphaseProxy& proxy = *body->getBroadphaseHandle();
        EXPECT_LT(leafMax(*body).x() - leafMin(*body).x(),
                  proxy.m_aabbMax.x() - proxy.m_aabbMin.x() + gDbvtMargin);
    }
    EXPECT_THROW(broadphase.setFraction(0), std::invalid_argument);
}

TEST(SizeScaledBroadphase, AHeapOfChipsMakesFewerPairs) {
    // 1 cm chips 6 cm apart: their boxes (widened by the 2 cm contact breaking threshold) are
    // about 1 cm apart, Bullet's leaves (5 cm more on every side) overlap.
    Drift bullet(std::make_unique<btDbvtBroadphase>(), 6, btScalar(0.01), btScalar(0.06), btScalar(0.3));
    Drift scaled(std::make_unique<SizeScaledBroadphase>(btScalar(0.25)), 6, btScalar(0.01), btScalar(0.06),
                 btScalar(0.3));
    const long long bulletPairs = pairsOver(bullet, 50), scaledPairs = pairsOver(scaled, 50);
    EXPECT_GT(bulletPairs, 10000);
    EXPECT_LT(scaledPairs, bulletPairs / 10) << "Bullet's broadphase " << bulletPairs;
}

TEST(SizeScaledBroadphase, NonPositiveFractionIsRejected) {
    EXPECT_THROW(SizeScaledBroadphase(0), std::invalid_argument);
    EXPECT_THROW(SizeScaledBroadphase(-1), std::invalid_argument);
}
