// SPDX-License-Identifier: Zlib
// Time from impact to spawned fragments: the bunny of demos/scenes/bunny_smash.json at
// 1,000 BEM triangles, hit by the steel ball, per fracture method. The step that breaks it is
// split into BEM (remesh, assembly, factorisation, solves), fracture (SIFs, initiation,
// propagation), geometry (level set, cuts, segmentation, fragment meshes), swap (restore, spawn,
// separate) and Bullet (the discarded step and its replay: the rest of the step's wall time);
// "before" is the time of earlier steps since the impact (engine calls whose cracks did not yet
// separate anything), "total" the wall time from the impact step to the fragments.
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <cstdio>
#include <string>

using namespace btfracture;

namespace {

struct FirstEvent : FractureListener {
    bool seen = false;
    FractureEventInfo info;
    int fragments = 0;
    void onFractureEvent(btFractureRigidBody&, const std::vector<btFractureRigidBody*>& pieces,
                         const FractureEventInfo& event) override {
        if (seen) return;
        seen = true;
        info = event;
        fragments = static_cast<int>(pieces.size());
    }
};

}  // namespace

int main() {
    const std::string file = std::string(BTFRACTURE_MESH_DIR) + "/../scenes/bunny_smash.json";
    std::printf("%-7s %9s %7s %7s %9s %7s %7s %8s %8s %9s %9s\n", "method", "fragments", "bem_s", "crack_s",
                "geometry_s", "swap_s", "bullet_s", "before_s", "total_s", "crack_tris", "duration_us");
    for (FractureMethod method : {FractureMethod::Full, FractureMethod::Estimated, FractureMethod::Hybrid}) {
        Scene scene = readSceneFile(file);
        overrideFractureMethod(scene, method);
        for (SceneBody& b : scene.bodies)
            if (b.fracture.fracturable) {
                b.fracture.bemTriangleTarget = 1000;
                b.fracture.hybridElementThreshold = 1100;  // switches to EST once cracks add 100 triangles
            }
        FractureSceneWorldFactory factory(scene.effects.seed);
        SceneWorld world(scene, factory);
        auto& fractureWorld = dynamic_cast<btFractureDynamicsWorld&>(world.world());
        FirstEvent first;
        fractureWorld.addFractureListener(&first);
        // From the first step in which the engine ran (the impact) to the step that spawned
        // fragments; earlier engine calls (cracks that did not yet separate) count as "before".
        double stepSeconds = 0.0, sinceImpact = 0.0;
        for (int s = 0; s < scene.world.steps && !first.seen; ++s) {
            const auto callsBefore = fractureWorld.fractureStatistics().engineCalls;
            Timer timer;
            world.stepFrame();
            stepSeconds = timer.seconds();
            if (sinceImpact > 0.0 || fractureWorld.fractureStatistics().engineCalls > callsBefore)
                sinceImpact += stepSeconds;
        }
        if (!first.seen) {
            std::printf("%-7s nothing broke\n", toString(method));
            continue;
        }
        const FractureEventInfo& e = first.info;
        const double bullet = stepSeconds - e.engineSeconds - e.swapSeconds;
        std::printf("%-7s %9d %7.2f %7.2f %9.2f %7.3f %7.3f %8.2f %8.2f %9d %9.1f\n", toString(method),
                    first.fragments, e.engineTimings.bem, e.engineTimings.fracture, e.engineTimings.geometry,
                    e.swapSeconds, bullet, sinceImpact - stepSeconds, sinceImpact, e.crackTriangles,
                    1e6 * e.contactDuration);
        std::printf("METRIC impact_to_fragments_bunny_1k_%s_s %.3f s\n", toString(method), sinceImpact);
        fractureWorld.removeFractureListener(&first);
    }
    return 0;
}
