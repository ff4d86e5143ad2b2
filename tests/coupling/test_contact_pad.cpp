// SPDX-License-Identifier: Zlib
// ContactPad and btFractureDynamicsWorld::updateAabbs: a breakable body's broadphase box is its
// shape's box padded by its own contact breaking threshold instead of Bullet's 2 cm, so chips a
// centimetre apart are no pair, while every pair within its manifold's threshold still is.
#include <btFracture/core/Material.h>
#include <btFracture/dynamics/ContactPad.h>
#include <btFracture/dynamics/SizeScaledBroadphase.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <btBulletDynamicsCommon.h>

#include "../support/BroadphaseBoxes.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

using namespace btfracture;
using btfracture::test::boxesOverlap;

namespace {

// No gravity; n x n x n chips (cubes of edge `edge`, `spacing` apart) of breakable bodies or plain
// Bullet boxes, drifting at up to 0.35 m/s and turning at up to 35 rad/s in seeded random
// directions (`speed` 1) or still (0), 240 Hz, no fracture (no engine).
struct Chips {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    SizeScaledBroadphase broadphase;  // the scene world's
    btSequentialImpulseConstraintSolver solver;
    btFractureDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
    btBoxShape cube;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    Chips(bool breakable, int n, btScalar edge, btScalar spacing, btScalar speed = 1)
        : cube(btVector3(edge, edge, edge) / 2) {
        cube.setMargin(btScalar(0.001));  // Bullet's 4 cm would exceed the chip
        world.setGravity(btVector3(0, 0, 0));
        std::mt19937 random(11);
        std::uniform_real_distribution<float> unit(-1, 1);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    const btTransform pose(
                        btQuaternion(btVector3(unit(random), unit(random), unit(random)).normalized(),
                                     unit(random)),
                        btVector3(btScalar(i), btScalar(j), btScalar(k)) * spacing);
                    std::unique_ptr<btRigidBody> body;
                    if (breakable) {
                        body = std::make_unique<btFractureRigidBody>(Material::glass(), cube,
                                                                     FractureBodySettings{}, pose);
                    } else {
                        btVector3 inertia;
                        cube.calculateLocalInertia(1, inertia);
                        body = std::make_unique<btRigidBody>(
                            btRigidBody::btRigidBodyConstructionInfo(1, nullptr, &cube, inertia));
                        body->setWorldTransform(pose);
                    }
                    body->setLinearVelocity(btVector3(unit(random), unit(random), unit(random)) *
                                            btScalar(0.2) * speed);
                    body->setAngularVelocity(btVector3(unit(random), unit(random), unit(random)) *
                                             btScalar(20) * speed);
                    body->setActivationState(DISABLE_DEACTIVATION);
                    world.addRigidBody(body.get());
                    bodies.push_back(std::move(body));
                }
    }
    void step() { world.stepSimulation(btScalar(1.0 / 240), 0); }
};

// Distance between two bodies' shapes, margins included, by GJK and EPA.
btScalar distance(const btRigidBody& a, const btRigidBody& b) {
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector gjk(static_cast<const btConvexShape*>(a.getCollisionShape()),
                          static_cast<const btConvexShape*>(b.getCollisionShape()), &simplex, &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = a.getWorldTransform();
    input.m_transformB = b.getWorldTransform();
    btPointCollector result;
    gjk.getClosestPoints(input, result, nullptr);
    return result.m_hasResult ? result.m_distance : BT_LARGE_FLOAT;
}

}  // namespace

TEST(ContactPad, BreakableBodiesArePaddedByTheirThresholdOthersByBullets) {
    Chips breakable(true, 1, btScalar(0.01), 0, 0), plain(false, 1, btScalar(0.01), 0, 0);
    // Bullet's box of a body just added has no pad; the world's first step pads it.
    EXPECT_EQ(broadphasePad(*breakable.bodies[0]), btScalar(0));
    for (Chips* chips : {&breakable, &plain}) {
        chips->step();
        const btRigidBody& body = *chips->bodies[0];
        btVector3 low, high;
        body.getCollisionShape()->getAabb(body.getWorldTransform(), low, high);
        const btBroadphaseProxy& proxy = *body.getBroadphaseHandle();
        const btScalar pad = low.x() - proxy.m_aabbMin.x();
        if (chips == &plain) {
            EXPECT_NEAR(pad, gContactBreakingThreshold, 1e-6);
        } else {
            const btScalar threshold =
                body.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold);
            EXPECT_NEAR(pad, threshold, 1e-6);
            EXPECT_LT(pad, gContactBreakingThreshold / 20) << "a 1 cm chip's threshold is about 0.02 x 1 cm";
            EXPECT_NEAR(broadphasePad(body), pad, 1e-7);
        }
    }
}

// 216 chips of 1 cm, 1.4 cm apart, drifting and turning for 120 steps: every pair of breakable
// chips within its manifold's contact breaking threshold has overlapping boxes (a broadphase
// pair), and they make far fewer pairs than the same chips as plain Bullet boxes.
TEST(ContactPad, ChipsWithinTheirThresholdStayPairsAndFarOnesDoNot) {
    Chips breakable(true, 6, btScalar(0.01), btScalar(0.014)),
        plain(false, 6, btScalar(0.01), btScalar(0.014));
    long long breakablePairs = 0, plainPairs = 0, close = 0;
    for (int s = 0; s < 120; ++s) {
        breakable.step();
        plain.step();
        breakablePairs += breakable.broadphase.getOverlappingPairCache()->getNumOverlappingPairs();
        plainPairs += plain.broadphase.getOverlappingPairCache()->getNumOverlappingPairs();
        if (s % 10 != 0) continue;
        breakable.world.updateAabbs();  // the boxes at the poses the step ended with
        const auto& bodies = breakable.bodies;
        for (std::size_t i = 0; i < bodies.size(); ++i)
            for (std::size_t j = i + 1; j < bodies.size(); ++j) {
                const btScalar threshold = btMin(
                    bodies[i]->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold),
                    bodies[j]->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
                if (!(distance(*bodies[i], *bodies[j]) < threshold)) continue;
                ++close;
                ASSERT_TRUE(
                    boxesOverlap(*bodies[i]->getBroadphaseHandle(), *bodies[j]->getBroadphaseHandle()))
                    << "chips " << i << " and " << j << " at step " << s;
            }
    }
    EXPECT_GT(close, 20) << "the chips meet";
    RecordProperty("close", int(close));
    RecordProperty("pairs", int(breakablePairs));
    RecordProperty("plain_pairs", int(plainPairs));
    EXPECT_LT(breakablePairs, plainPairs / 2) << "plain Bullet boxes " << plainPairs;
}

// Two still, axis-aligned 1 cm breakable cubes face to face: within their contact breaking
// threshold their boxes overlap and one collision pass finds their contact; 10 thresholds
// (1.8 mm) apart their boxes are apart (Bullet's 2 cm pads would overlap) and there is none.
TEST(ContactPad, FaceToFaceCubesOverlapWithinTheThresholdOnly) {
    for (const double gapInThresholds : {0.5, 0.9, 10.0}) {
        Chips chips(true, 1, btScalar(0.01), 0, 0);
        btRigidBody& first = *chips.bodies[0];
        first.setWorldTransform(btTransform::getIdentity());
        first.setInterpolationWorldTransform(btTransform::getIdentity());
        const btScalar threshold =
            first.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold);
        const btScalar gap = btScalar(gapInThresholds) * threshold;
        btFractureRigidBody second(
            Material::glass(), chips.cube, FractureBodySettings{},
            btTransform(btQuaternion::getIdentity(), btVector3(btScalar(0.01) + gap, 0, 0)));
        chips.world.addRigidBody(&second);
        ASSERT_NEAR(distance(first, second), gap, 1e-6) << "shape + margin is the cube";
        chips.world.performDiscreteCollisionDetection();
        EXPECT_EQ(boxesOverlap(*first.getBroadphaseHandle(), *second.getBroadphaseHandle()),
                  gapInThresholds < 1)
            << gapInThresholds << " thresholds apart";
        int contacts = 0;
        for (int m = 0; m < chips.dispatcher.getNumManifolds(); ++m)
            contacts += chips.dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
        EXPECT_EQ(contacts > 0, gapInThresholds < 1) << gapInThresholds << " thresholds apart";
        chips.world.removeRigidBody(&second);
    }
}
