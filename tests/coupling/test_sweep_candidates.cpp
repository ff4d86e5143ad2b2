// SPDX-License-Identifier: Zlib
// SweepCandidateFilter: Bullet's CCD sweeps with the candidates they cannot hit left out give the
// same motion, bit for bit, as Bullet's own sweeps, and an overlap filter the application
// installed keeps deciding (and is back on the pair cache after the step).
#include <btFracture/dynamics/SweepCandidateFilter.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

using namespace btfracture;

namespace {

// Bullet's world with its sweeps filtered, as btFractureDynamicsWorld does it.
struct FilteredWorld : btDiscreteDynamicsWorld {
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    void integrateTransforms(btScalar timeStep) override {
        SweepCandidateFilter filter(*getBroadphase()->getOverlappingPairCache(), timeStep);
        btDiscreteDynamicsWorld::integrateTransforms(timeStep);
        count(filter);
    }
    void createPredictiveContacts(btScalar timeStep) override {
        SweepCandidateFilter filter(*getBroadphase()->getOverlappingPairCache(), timeStep);
        btDiscreteDynamicsWorld::createPredictiveContacts(timeStep);
        count(filter);
    }
    void count(const SweepCandidateFilter& filter) {
        queries += filter.queries();
        rejected += filter.rejected();
        rejectedBySupport += filter.rejectedBySupport();
    }
    long long queries = 0, rejected = 0, rejectedBySupport = 0;
};

// Bodies the application's filter keeps out of every pair and sweep (user index 1).
struct GhostFilter : btOverlapFilterCallback {
    bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override {
        const auto ghost = [](btBroadphaseProxy* p) {
            return static_cast<const btCollisionObject*>(p->m_clientObject)->getUserIndex() == 1;
        };
        return !ghost(a) && !ghost(b);
    }
};

// No gravity; a 9 x 9 x 3 lattice of 1 cm cubes 3 cm apart (every cube within the broadphase's
// 5 cm leaf margin of its neighbours) and eight 1 cm balls crossing it at 15-25 m/s (6-10 cm a
// step at 250 Hz: they would tunnel without CCD) with CCD on (threshold 5 mm, swept sphere 4 mm).
// The cubes of the bottom layer (z = 0) are ghosts (user index 1) where the test asks for them.
// With `plates`, the cubes are 24 x 24 x 2 mm plates and the odd balls fly midway between two
// layers (1.5 cm from the plates, within the plates' 1.7 cm bounding radius), the even ones
// 0.5 mm above a layer's mid-plane, into the plates' edges.
struct Lattice {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::unique_ptr<btDiscreteDynamicsWorld> world;
    btBoxShape cube{btVector3(0.005f, 0.005f, 0.005f)};
    btBoxShape plate{btVector3(0.012f, 0.012f, 0.001f)};
    btSphereShape ball{0.005f};
    std::vector<std::unique_ptr<btRigidBody>> cubes, balls;
    GhostFilter ghosts;

    Lattice(bool filtered, bool withGhosts, bool plates = false) {
        if (filtered)
            world = std::make_unique<FilteredWorld>(&dispatcher, &broadphase, &solver, &config);
        else
            world = std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, &broadphase, &solver, &config);
        world->setGravity(btVector3(0, 0, 0));
        if (withGhosts) broadphase.getOverlappingPairCache()->setOverlapFilterCallback(&ghosts);
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 9; ++j)
                for (int k = 0; k < 3; ++k) {
                    auto body =
                        makeBody(plates ? plate : cube, 0.001f, btVector3(0.03f * i, 0.03f * j, 0.03f * k));
                    body->setUserIndex(k == 0 ? 1 : 0);
                    cubes.push_back(std::move(body));
                }
        for (int b = 0; b < 8; ++b) {
            // Each aimed at a row of cubes (y = 3 cm j, z = 3 cm k), up to 4 mm off its axis.
            const btScalar y = btScalar(0.03) * b + btScalar(0.002) * (b % 3);
            const btScalar z =
                btScalar(0.03) * (b % 3) + (plates ? btScalar(b % 2 ? 0.015 : 0.0005) : btScalar(0));
            auto body = makeBody(ball, 0.002f, btVector3(-0.2f, y, z));
            body->setLinearVelocity(btVector3(btScalar(15.0 + 10.0 * b / 7.0), 0, 0));
            body->setCcdMotionThreshold(0.005f);
            body->setCcdSweptSphereRadius(0.004f);
            balls.push_back(std::move(body));
        }
    }
    ~Lattice() {
        for (auto& b : balls) world->removeRigidBody(b.get());
        for (auto& c : cubes) world->removeRigidBody(c.get());
    }
    std::unique_ptr<btRigidBody> makeBody(btCollisionShape& shape, btScalar mass, const btVector3& at) {
        btVector3 inertia;
        shape.calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &shape, inertia);
        info.m_startWorldTransform.setIdentity();
        info.m_startWorldTransform.setOrigin(at);
        auto body = std::make_unique<btRigidBody>(info);
        body->setActivationState(DISABLE_DEACTIVATION);
        world->addRigidBody(body.get());
        return body;
    }
    void run(int steps) {
        for (int s = 0; s < steps; ++s) world->stepSimulation(btScalar(0.004), 0, btScalar(0.004));
    }
    // Every body's pose and velocities.
    std::vector<btScalar> state() const {
        std::vector<btScalar> values;
        for (const auto* list : {&cubes, &balls})
            for (const auto& body : *list) {
                const btTransform& t = body->getWorldTransform();
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) values.push_back(t.getBasis()[r][c]);
                for (const btVector3& v :
                     {t.getOrigin(), body->getLinearVelocity(), body->getAngularVelocity()})
                    values.insert(values.end(), {v.x(), v.y(), v.z()});
            }
        return values;
    }
};

void expectSameState(const std::vector<btScalar>& a, const std::vector<btScalar>& b) {
    ASSERT_EQ(a.size(), b.size());
    int differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    EXPECT_EQ(differing, 0) << "of " << a.size() << " pose and velocity values";
}

}  // namespace

TEST(SweepCandidateFilter, SameMotionAsBulletsSweepsWithMostCandidatesLeftOut) {
    Lattice bullet(false, false), ours(true, false);
    bullet.run(40);
    ours.run(40);
    expectSameState(bullet.state(), ours.state());
    const auto& world = static_cast<const FilteredWorld&>(*ours.world);
    // The balls are swept while they move faster than 5 mm a step; the lattice's cubes near their
    // paths are the candidates, most of them well off the path (98 % here).
    EXPECT_GT(world.queries, 1000);
    EXPECT_GT(world.rejected, world.queries * 9 / 10);
    EXPECT_LT(world.rejected, world.queries);
    // The balls hit cubes (found by the sweeps: they move 6-10 cm a step through 1 cm cubes).
    int hit = 0;
    for (const auto& c : ours.cubes) hit += c->getLinearVelocity().length2() > btScalar(0);
    EXPECT_GE(hit, 40);
}

TEST(SweepCandidateFilter, PlatesBesideThePathLeftOutByTheirSupportPlane) {
    Lattice bullet(false, false, true), ours(true, false, true);
    bullet.run(40);
    ours.run(40);
    expectSameState(bullet.state(), ours.state());
    const auto& world = static_cast<const FilteredWorld&>(*ours.world);
    // The plates next to the odd balls' paths reach them with their bounding spheres, not with
    // their faces: the support plane leaves them out.
    EXPECT_GT(world.rejectedBySupport, 100);
    EXPECT_LT(world.rejected, world.queries);
    int hit = 0;
    for (const auto& c : ours.cubes) hit += c->getLinearVelocity().length2() > btScalar(0);
    EXPECT_GE(hit, 10);
}

TEST(SweepCandidateFilter, ApplicationsOverlapFilterStillDecides) {
    Lattice bullet(false, true), ours(true, true);
    bullet.run(40);
    ours.run(40);
    expectSameState(bullet.state(), ours.state());
    EXPECT_EQ(ours.broadphase.getOverlappingPairCache()->getOverlapFilterCallback(), &ours.ghosts);
    // No ghost cube was touched; the balls aimed at them (z = 0) passed.
    for (const auto& c : ours.cubes) {
        if (c->getUserIndex() == 1) {
            EXPECT_EQ(c->getLinearVelocity().length2(), btScalar(0));
        }
    }
    for (std::size_t b = 0; b < ours.balls.size(); b += 3)
        EXPECT_EQ(ours.balls[b]->getLinearVelocity(), btVector3(btScalar(15.0 + 10.0 * b / 7.0), 0, 0))
            << "ball " << b;
}
