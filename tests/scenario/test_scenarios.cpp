// CTest collision scenarios (issue 7): each paper scene of demos/scenes, at reduced BEM and
// collision resolution, runs headless in the runner's world (SceneWorld built by
// FractureSceneWorldFactory, SceneFractureListener keeping names) and is checked:
//  - the bodies expected to break do, first within the expected time window (the impact);
//  - at every event, fragment volumes sum to the parent's within 3 % (voxel rim + dropped dust),
//    and the fragments' linear momentum is the parent's pre-step rigid motion carried over:
//    sum m_i v_i = m v + w x sum m_i (c_i - c) (m: fragment mass) to 1e-4 of M (|v| + |w| L),
//    beyond what the separation push can explain (|w| m push);
//  - nothing becomes non-finite, falls through the ground or leaves a 30 m box;
//  - the same scene twice gives the same events and fragment volumes.
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
    double firstAfter, firstBefore;     // window of the first event [s]
};

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
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    EXPECT_NE(fractureWorld, nullptr);
    FractureRecorder recorder;
    const double step = scene.world.dt / scene.world.substeps;
    FractureRecorderListener names(recorder, step);
    for (const auto& body : world.bodies())
        if (const btFractureRigidBody* b = btFractureRigidBody::upcast(body.rigidBody))
            names.addOriginal(*b, body.name);
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
    // body's largest half extent is passing through it; shallower it may dip in (bowl_drop at stop
    // 21: a 17 mm^3 speck 6.2 cm deep for 4 steps, then back up). At the end, none may lie wholly
    // below the ground (support/GroundCheck.h).
    double depthLimit = 0.0;  // [m]
    for (const auto& body : world.bodies()) {
        if (body.plane) continue;
        btVector3 lo, hi;
        body.rigidBody->getAabb(lo, hi);
        const Eigen::Vector3d extent = eig(hi - lo);
        depthLimit = std::max(depthLimit, 0.5 * extent.maxCoeff());
    }
    for (int s = 0; s < scene.world.steps; ++s) {
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
    EXPECT_GE(a.events.front().time, expect.firstAfter) << expect.scene;
    EXPECT_LE(a.events.front().time, expect.firstBefore) << expect.scene;
    for (const char* body : expect.breaking)
        EXPECT_TRUE(std::any_of(a.events.begin(), a.events.end(),
                                [&](const FractureEventCheck& e) { return e.body == body; }))
            << expect.scene << ": " << body << " did not break";
    for (const FractureEventCheck& e : a.events) {
        EXPECT_GE(e.fragments, 2);
        EXPECT_NEAR(e.volumeRatio, 1.0, 0.03) << expect.scene << " at t = " << e.time;
        EXPECT_NEAR(e.massRatio, 1.0, 0.03) << expect.scene << " at t = " << e.time;
        EXPECT_LT(e.momentumError, 1e-4) << expect.scene << " at t = " << e.time;
    }
    // Same input, same output.
    const Outcome b = runScenario(expect);
    ASSERT_EQ(a.events.size(), b.events.size());
    for (size_t i = 0; i < a.events.size(); ++i) EXPECT_EQ(a.events[i].volumes, b.events[i].volumes);
}

// Steps cover the impact with a margin; windows bracket the first contact of the projectile or
// the ground (free fall t = sqrt(2 h / g)). falling_boxes names no box: each glass block lands
// near its toughness (box2's fronts arrest at K/K_c 0.98 in one build and ran on in another, the
// difference a 1-ulp eigenvalue), so which one breaks first follows the rounding; one of them
// must, within the window of the first two landings (3 m and 4 m: 0.78 and 0.90 s).
INSTANTIATE_TEST_SUITE_P(PaperScenes, Scenario,
                         ::testing::Values(Expect{"column_bunny", 100, {"column"}, 0.15, 0.30},
                                           Expect{"bunny_smash", 30, {"bunny"}, 0.0, 0.08},
                                           Expect{"brick", 60, {"brick"}, 0.0, 0.05},
                                           Expect{"falling_boxes", 500, {}, 0.75, 1.0},
                                           Expect{"bowl_drop", 420, {"bowl"}, 0.70, 0.85},
                                           Expect{"armadillos", 40, {"left", "right"}, 0.02, 0.08},
                                           Expect{"window_pane", 15, {"pane"}, 0.005, 0.02}),
                         [](const ::testing::TestParamInfo<Expect>& info) {
                             return std::string(info.param.scene);
                         });

}  // namespace
}  // namespace btfracture
