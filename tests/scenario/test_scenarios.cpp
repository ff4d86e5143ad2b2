// SPDX-License-Identifier: Zlib
// CTest collision scenarios: each paper scene of demos/scenes, at reduced BEM and collision
// resolution, runs headless in the runner's world (SceneWorld built by FractureSceneWorldFactory,
// SceneFractureListener keeping names) and is checked:
//  - the bodies expected to break do, first within the expected time window (the impact);
//  - at every event, fragment volumes sum to the parent's within 3 % (voxel rim + dropped dust),
//    and the fragments' linear momentum is the parent's pre-step rigid motion carried over:
//    sum m_i v_i = m v + w x sum m_i (c_i - c) (m: fragment mass) to 1e-4 of M (|v| + |w| L),
//    beyond what the separation push can explain (|w| m push);
//  - at every event, the fracture pipeline (swap, separation push, replayed step and the steps
//    after it while Bullet resolves the overlaps left) adds at most 2 % of the kinetic energy the
//    event started with (dynamics/FractureEnergy.h);
//  - nothing becomes non-finite, falls through the ground or leaves a 30 m box;
//  - the same scene twice gives the same events and fragment volumes;
//  - margin: every scene breaks the same bodies with its driving speed 10 % lower (thrown bodies
//    slower, dropped bodies from 0.81 of their height), so no outcome sits on a knife edge.
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneFractureListener.h>
#include <btFracture/io/SceneWorld.h>

#include "../support/FractureEventAccounting.h"
#include "../support/GroundCheck.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace btfracture {
namespace {

Eigen::Vector3d eig(const btVector3& v) {
    return Eigen::Vector3d(v.x(), v.y(), v.z());
}

using test::FractureEventAccounting;
using test::FractureEventCheck;

struct Expect {
    const char* scene;
    int steps;
    std::vector<const char*> breaking;  // bodies that must break at least once
    double firstAfter, firstBefore;     // window of the first event [s] at the scene's own speeds
    std::vector<const char*> dropped;   // bodies falling from rest onto the ground plane
    double speedScale = 1.0;            // driving speeds x this (margin runs)
};

void PrintTo(const Expect& e, std::ostream* os) {
    *os << e.scene << " at " << e.speedScale << " x its driving speeds";
}

Expect slower(Expect e) {
    e.speedScale = 0.9;
    return e;
}

struct Outcome {
    std::vector<FractureEventCheck> events;
    bool finite = true, inside = true;
    std::string problem;
};

Outcome runScenario(const Expect& expect) {
    Scene scene = readSceneFile(std::string(BTFRACTURE_SCENE_DIR) + "/" + expect.scene + ".json");
    scene.world.steps = expect.steps;
    for (SceneBody& b : scene.bodies)
        if (b.fracture.fracturable) {  // test-sized resolutions
            b.fracture.bemTriangleTarget = std::min(b.fracture.bemTriangleTarget, 500);
            b.fracture.collisionTriangleTarget = std::min(b.fracture.collisionTriangleTarget, 2000);
            b.fracture.maxRefractureDepth = 0;
        }
    // Driving speeds: thrown bodies move s times as fast; dropped ones fall from s^2 of their
    // height above the ground (impact speed sqrt(2 g h)).
    const double s = expect.speedScale;
    for (SceneBody& b : scene.bodies) {
        b.linearVelocity *= s;
        b.angularVelocity *= s;
    }
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    for (const char* name : expect.dropped) {
        const auto body = std::find_if(world.bodies().begin(), world.bodies().end(),
                                       [&](const auto& b) { return b.name == name; });
        EXPECT_NE(body, world.bodies().end()) << expect.scene << ": no body " << name;
        if (body == world.bodies().end()) continue;
        btVector3 lo, hi;
        body->rigidBody->getAabb(lo, hi);
        body->rigidBody->translate(btVector3(0, -btScalar((1.0 - s * s) * double(lo.y())), 0));
        body->rigidBody->setInterpolationWorldTransform(body->rigidBody->getWorldTransform());
    }
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    EXPECT_NE(fractureWorld, nullptr);
    FractureRecorder recorder;
    const double step = scene.world.dt / scene.world.substeps;
    FractureRecorderListener names(recorder, step);
    SceneFractureListener sceneListener(names, world);
    FractureEventAccounting probe(step,
                                  [&](const btFractureRigidBody& parent) { return names.nameOf(&parent); });
    // Order: the probe reads the parent before SceneWorld retires it; names come from the
    // recorder, which the scene listener calls.
    fractureWorld->addFractureListener(&probe);
    fractureWorld->addFractureListener(&sceneListener);

    Outcome out;
    const bool ground = !scene.bodies.empty() && scene.bodies[0].shape.type == SceneShapeType::Plane;
    // Tunnelling, as in tests/stability: a centre of mass deeper in the ground than the largest
    // body's largest half extent is passing through it; shallower it may dip in (a speck of the
    // bowl 6 cm deep for 4 steps, then back up). At the end, none may lie wholly below the ground
    // (support/GroundCheck.h).
    double depthLimit = 0.0;  // [m]
    for (const auto& body : world.bodies()) {
        if (body.plane) continue;
        btVector3 lo, hi;
        body.rigidBody->getAabb(lo, hi);
        const Eigen::Vector3d extent = eig(hi - lo);
        depthLimit = std::max(depthLimit, 0.5 * extent.maxCoeff());
    }
    // The run ends no sooner than kSettle after its last fracture event, so that the end checks
    // do not catch fragments in the middle of their spawning impact (a chip spawned at its
    // parent's pose 14 mm deep in the ground by a 7 m/s landing), at most 4 kSettle late.
    constexpr double kSettle = 0.05;  // [s]
    const double end = scene.world.steps * scene.world.dt;
    auto keepStepping = [&](int s) {
        const double t = s * scene.world.dt;
        if (s < scene.world.steps) return true;
        return !probe.events.empty() && t < probe.events.back().time + kSettle && t < end + 4 * kSettle;
    };
    for (int s = 0; keepStepping(s); ++s) {
        world.stepFrame();
        for (const auto& body : world.bodies()) {
            const Eigen::Vector3d p = eig(body.rigidBody->getCenterOfMassPosition());
            if (!p.allFinite() || !eig(body.rigidBody->getLinearVelocity()).allFinite()) {
                out.finite = false;
                out.problem = body.name + " non-finite at step " + std::to_string(s);
            }
            if (body.plane) continue;
            if (p.cwiseAbs().maxCoeff() > 30.0 || (ground && p.y() < -depthLimit)) {
                out.inside = false;
                out.problem = body.name + " left the scene at step " + std::to_string(s) + ": (" +
                              std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
                              std::to_string(p.z()) + ")";
            }
        }
        if (!out.finite) break;
    }
    fractureWorld->finishEnergyAudits();
    for (const auto& body : world.bodies()) {
        if (!ground || body.plane) continue;
        if (const std::string below = test::whollyBelowGround(*body.rigidBody); !below.empty()) {
            out.inside = false;
            out.problem = body.name + below;
        }
    }
    out.events = probe.events;
    return out;
}

class Scenario : public ::testing::TestWithParam<Expect> {};

TEST_P(Scenario, BreaksWhereExpectedConservingVolumeAndMomentum) {
    const Expect& expect = GetParam();
    const Outcome a = runScenario(expect);
    EXPECT_TRUE(a.finite) << a.problem;
    EXPECT_TRUE(a.inside) << a.problem;
    ASSERT_FALSE(a.events.empty()) << expect.scene << ": nothing broke";
    // Slower thrown bodies arrive later (t ~ 1/s), lower dropped ones earlier (t ~ s).
    const double early = std::min(expect.speedScale, 1.0 / expect.speedScale);
    EXPECT_GE(a.events.front().time, expect.firstAfter * early) << expect.scene;
    EXPECT_LE(a.events.front().time, expect.firstBefore / early) << expect.scene;
    for (const char* body : expect.breaking)
        EXPECT_TRUE(std::any_of(a.events.begin(), a.events.end(),
                                [&](const FractureEventCheck& e) { return e.body == body; }))
            << expect.scene << ": " << body << " did not break";
    for (const FractureEventCheck& e : a.events) {
        EXPECT_GE(e.fragments, 2);
        EXPECT_NEAR(e.volumeRatio, 1.0, 0.03) << expect.scene << " at t = " << e.time;
        EXPECT_NEAR(e.massRatio, 1.0, 0.03) << expect.scene << " at t = " << e.time;
        EXPECT_LT(e.momentumError, 1e-4) << expect.scene << " at t = " << e.time;
        ASSERT_TRUE(e.hasEnergy) << expect.scene << " at t = " << e.time;
        const FractureEnergyAudit& k = e.energy;
        std::printf(
            "%s at t = %.4f s: %s kinetic energy [J] body %.4g, partners %.4g, swap %.4g, separated %.4g, "
            "replay %.4g, following max %.4g (%d steps); potential gain swap %.3g, separated %.3g J; "
            "world energy gain %.4g J (%.3g of the start)\n",
            expect.scene, e.time, e.body.c_str(), k.bodyKinetic, k.partnersKinetic, k.swapKinetic,
            k.separatedKinetic, k.replayKinetic, k.followingKinetic, k.followingSteps, k.swapPotentialGain,
            k.separatedPotentialGain, k.worldGain, k.addedFraction());
        // Fragments whose separation push is capped (FragmentSeparation) leave their overlap to
        // the solver: bunny_smash at 0.9x adds 1.31 % that way (28 of 32 pushes capped).
        EXPECT_LE(k.addedFraction(), 0.02) << expect.scene << " at t = " << e.time << ": " << e.body;
    }
    if (expect.speedScale != 1.0) return;
    // Same input, same output.
    const Outcome b = runScenario(expect);
    ASSERT_EQ(a.events.size(), b.events.size());
    for (size_t i = 0; i < a.events.size(); ++i) EXPECT_EQ(a.events[i].volumes, b.events[i].volumes);
}

// Steps cover the impact with a margin; windows bracket the first contact of the projectile or
// the ground (free fall t = sqrt(2 h / g)). falling_boxes names no box: each glass block lands
// near its toughness, so which one breaks first follows the rounding; one of them must, within
// the window of the first two landings (3 m and 4 m: 0.78 and 0.90 s).
const std::vector<Expect> kScenes = {
    Expect{"column_bunny", 100, {"column"}, 0.15, 0.30, {}},
    Expect{"bunny_smash", 30, {"bunny"}, 0.0, 0.08, {}},
    Expect{"brick", 60, {"brick"}, 0.0, 0.05, {}},
    Expect{"falling_boxes", 500, {}, 0.75, 1.0, {"box1", "box2", "box3", "box4"}},
    Expect{"bowl_drop", 420, {"bowl"}, 0.70, 0.85, {"bowl"}},
    Expect{"armadillos", 40, {"left", "right"}, 0.02, 0.08, {}},
    Expect{"window_pane", 15, {"pane"}, 0.005, 0.02, {}},
};

std::string sceneName(const ::testing::TestParamInfo<Expect>& info) {
    return std::string(info.param.scene);
}

INSTANTIATE_TEST_SUITE_P(PaperScenes, Scenario, ::testing::ValuesIn(kScenes), sceneName);
INSTANTIATE_TEST_SUITE_P(PaperScenesTenPercentSlower, Scenario, ::testing::ValuesIn([] {
                             std::vector<Expect> v;
                             for (const Expect& e : kScenes) v.push_back(slower(e));
                             return v;
                         }()),
                         sceneName);

}  // namespace
}  // namespace btfracture
