// SPDX-License-Identifier: Zlib
// Idle overhead of btFractureDynamicsWorld: 500 bodies that never break (250 fracturable glass
// boxes with an unreachable impulse threshold and 250 plain steel spheres) dropped into a bin so
// that they collide and then rest in a pile, stepped in a btFractureDynamicsWorld (with the
// plane-split engine installed) and in a plain btDiscreteDynamicsWorld. Same scene, same
// process, interleaved in chunks of steps so that both see the same machine load.
//
// Prints METRIC idle_overhead_ratio (fracture world time / plain world time; goal <= 1.05), the
// per-step times, and whether both worlds end bit-identical (METRIC idle_worlds_bit_identical:
// they do not, since the fracture world collides breakable bodies its own way, with its own
// broadphase pads and pair handling, so contacts come in another order). Exits 1 when the hook
// called the engine, which no body here can reach.
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/PlaneSplitFractureEngine.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

using namespace btfracture;

namespace {

constexpr int kBodies = 500;
constexpr int kSteps = 1440;  // 6 s at 240 Hz: falling, colliding, then resting
constexpr int kChunk = 60;
constexpr btScalar kDt = btScalar(1.0 / 240.0);

struct Pile {
    explicit Pile(bool fracture) {
        if (fracture) {
            auto w = std::make_unique<btFractureDynamicsWorld>(&dispatcher, &broadphase, &solver, &config);
            w->setFractureEngine(std::make_unique<PlaneSplitFractureEngine>());
            world = std::move(w);
        } else {
            world = std::make_unique<btDiscreteDynamicsWorld>(&dispatcher, &broadphase, &solver, &config);
        }
        world->setGravity(btVector3(0, btScalar(-9.81), 0));
        // Floor and four walls of a 2 m x 2 m bin.
        const btVector3 halves[5] = {{2, btScalar(0.5), 2},
                                     {btScalar(0.1), 2, 2},
                                     {btScalar(0.1), 2, 2},
                                     {2, 2, btScalar(0.1)},
                                     {2, 2, btScalar(0.1)}};
        const btVector3 origins[5] = {{0, btScalar(-0.5), 0},
                                      {btScalar(1.1), 2, 0},
                                      {btScalar(-1.1), 2, 0},
                                      {0, 2, btScalar(1.1)},
                                      {0, 2, btScalar(-1.1)}};
        for (int i = 0; i < 5; ++i) {
            shapes.push_back(std::make_unique<btBoxShape>(halves[i]));
            statics.push_back(std::make_unique<btRigidBody>(
                btRigidBody::btRigidBodyConstructionInfo(0, nullptr, shapes.back().get())));
            statics.back()->getWorldTransform().setOrigin(origins[i]);
            world->addRigidBody(statics.back().get());
        }
        FractureBodySettings never;
        never.impulseThreshold = 1e12;
        const btBoxShape box(btVector3(btScalar(0.06), btScalar(0.04), btScalar(0.05)));
        btSphereShape* sphere = new btSphereShape(btScalar(0.05));
        shapes.emplace_back(sphere);
        btVector3 sphereInertia;
        const btScalar sphereMass = btScalar(4.1);
        sphere->calculateLocalInertia(sphereMass, sphereInertia);
        // A 10 x 10 grid of columns, 5 bodies high, alternating boxes and spheres, slightly jittered.
        for (int i = 0; i < kBodies; ++i) {
            const int column = i % 100, level = i / 100;
            const btScalar x = btScalar(-0.9 + 0.2 * (column % 10) + 0.013 * (level % 3));
            const btScalar z = btScalar(-0.9 + 0.2 * (column / 10) - 0.011 * (level % 2));
            const btScalar y = btScalar(0.3 + 0.25 * level + 0.02 * (column % 7));
            btTransform pose(btQuaternion(btVector3(1, 1, 0).normalized(), btScalar(0.3 * (i % 5))),
                             btVector3(x, y, z));
            std::unique_ptr<btRigidBody> body;
            if (i % 2 == 0) {
                body = std::make_unique<btFractureRigidBody>(Material::glass(), box, never, pose);
            } else {
                body = std::make_unique<btRigidBody>(
                    btRigidBody::btRigidBodyConstructionInfo(sphereMass, nullptr, sphere, sphereInertia));
                body->setWorldTransform(pose);
            }
            body->setActivationState(DISABLE_DEACTIVATION);  // resting bodies keep costing solver work
            body->setLinearVelocity(btVector3(0, btScalar(-2.0 - 0.01 * (i % 13)), 0));
            world->addRigidBody(body.get());
            bodies.push_back(std::move(body));
        }
    }
    ~Pile() {
        for (auto& b : bodies) world->removeRigidBody(b.get());
        for (auto& b : statics) world->removeRigidBody(b.get());
        world.reset();
    }
    double run(int steps) {
        Timer timer;
        for (int i = 0; i < steps; ++i) world->stepSimulation(kDt, 1, kDt);
        return timer.seconds();
    }

    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::unique_ptr<btDiscreteDynamicsWorld> world;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> statics;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
};

}  // namespace

int main() {
    Pile plain(false), fracture(true);
    double plainSeconds = 0.0, fractureSeconds = 0.0;
    std::vector<double> ratios;
    for (int done = 0, chunk = 0; done < kSteps; done += kChunk, ++chunk) {
        // Alternate which world goes first in a chunk.
        double p, f;
        if (chunk % 2 == 0) {
            p = plain.run(kChunk);
            f = fracture.run(kChunk);
        } else {
            f = fracture.run(kChunk);
            p = plain.run(kChunk);
        }
        plainSeconds += p;
        fractureSeconds += f;
        ratios.push_back(f / p);
    }
    std::sort(ratios.begin(), ratios.end());
    int identical = 1;
    for (std::size_t i = 0; i < plain.bodies.size(); ++i) {
        const btTransform& a = plain.bodies[i]->getWorldTransform();
        const btTransform& b = fracture.bodies[i]->getWorldTransform();
        if (std::memcmp(&a.getOrigin(), &b.getOrigin(), sizeof(btVector3)) != 0 ||
            std::memcmp(&a.getBasis(), &b.getBasis(), sizeof(btMatrix3x3)) != 0)
            identical = 0;
    }
    const auto* world = static_cast<btFractureDynamicsWorld*>(fracture.world.get());
    const FractureStatistics& s = world->fractureStatistics();
    std::printf(
        "bodies %d (250 fracturable boxes, 250 plain spheres), steps %d, contact manifolds at the end %d\n",
        kBodies, kSteps, fracture.dispatcher.getNumManifolds());
    std::printf("hook: %llu steps, %llu fracturable-body checks, %llu triggered, %llu engine calls\n",
                static_cast<unsigned long long>(s.steps), static_cast<unsigned long long>(s.bodiesChecked),
                static_cast<unsigned long long>(s.bodiesTriggered),
                static_cast<unsigned long long>(s.engineCalls));
    std::printf("METRIC plain_step_ms %.4f ms\n", 1e3 * plainSeconds / kSteps);
    std::printf("METRIC fracture_world_step_ms %.4f ms\n", 1e3 * fractureSeconds / kSteps);
    std::printf("METRIC idle_overhead_ratio %.4f ratio\n", fractureSeconds / plainSeconds);
    std::printf("METRIC idle_overhead_ratio_median_chunk %.4f ratio\n", ratios[ratios.size() / 2]);
    std::printf("METRIC idle_worlds_bit_identical %d bool\n", identical);
    return s.engineCalls == 0 ? 0 : 1;
}
