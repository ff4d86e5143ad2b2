// SPDX-License-Identifier: Zlib
// Does the ball split the free pane through? `window_pane` (2 cm glass, 2 kg steel ball at
// 25 m/s) over the first 0.2 s, in which the ball's events end, at 0.9, 0.95, 1.0, 1.05 and 1.1
// times the ball's speed: EST (the scene's method) and FULL, each with the scene's other settings
// (as `btfracture-run --method`). Prints the share of the pane's volume that its largest piece
// keeps (goal: at most 0.5 at every speed, so that the outcome sits on no knife edge) and the worst
// share per method:
//   METRIC window_pane_largest_piece_<method>_<speed> <share> ratio
//   METRIC window_pane_largest_piece_<method>_worst <share> ratio
//
//   bench_pane_split [--methods est,full] [--surface-seeds] [--scenes DIR]
// --surface-seeds: FULL seeds surface cracks (scene key effects.surface_seeds); its metrics are
// named full_surface_seeds.
// A few minutes per method on 2 cores.
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ThreadLimit.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneFractureListener.h>
#include <btFracture/io/SceneWorld.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace btfracture;
namespace fs = std::filesystem;

namespace {

constexpr int kSteps = 100;  // 0.2 s at the scene's 2 ms
const double kSpeeds[] = {0.9, 0.95, 1.0, 1.05, 1.1};

struct Split {
    double largestShare = 0.0;  // of the pane's volume
    int pieces = 0, events = 0;
    double seconds = 0.0;
};

Split run(const fs::path& scenes, FractureMethod method, bool surfaceSeeds, double speed) {
    Scene scene = readSceneFile((scenes / "window_pane.json").string());
    scene.world.steps = kSteps;
    scene.effects.outputs = SceneOutputFormats{};
    scene.effects.surfaceSeeds = surfaceSeeds;
    for (SceneBody& b : scene.bodies) {
        b.linearVelocity *= speed;
        b.angularVelocity *= speed;
        if (b.fracture.fracturable) b.fracture.method = method;
    }
    const Timer wall;
    const ThreadLimit threads(scene.run.threads);
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    if (!fractureWorld) throw Error("window_pane: no breakable body");
    FractureRecorder recorder;
    FractureRecorderListener names(recorder, scene.world.dt / scene.world.substeps);
    SceneFractureListener sceneListener(names, world);
    fractureWorld->addFractureListener(&sceneListener);
    for (int i = 0; i < scene.world.steps; ++i) world.stepFrame();
    recorder.close();
    Split s;
    s.largestShare = 1.0;  // unbroken
    s.events = recorder.events();
    if (s.events > 0) {
        s.largestShare = 0.0;
        for (const FractureRecorder::Fragment& f : recorder.fragments())
            if (f.original == "pane") {
                s.largestShare = std::max(s.largestShare, f.relativeVolume);
                ++s.pieces;
            }
    }
    s.seconds = wall.seconds();
    return s;
}

std::string speedTag(double speed) {
    char text[16];
    std::snprintf(text, sizeof text, "%.2f", speed);
    std::string tag = text;
    std::replace(tag.begin(), tag.end(), '.', 'p');
    return tag;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path scenes = fs::path(BTFRACTURE_MESH_DIR) / ".." / "scenes";
    std::vector<FractureMethod> methods = {FractureMethod::Estimated, FractureMethod::Full};
    bool surfaceSeeds = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--scenes" && i + 1 < argc) {
            scenes = argv[++i];
        } else if (arg == "--surface-seeds") {
            surfaceSeeds = true;
        } else if (arg == "--methods" && i + 1 < argc) {
            methods.clear();
            std::stringstream list(argv[++i]);
            for (std::string m; std::getline(list, m, ',');)
                methods.push_back(parseFractureMethod(m, "--methods"));
        } else {
            std::fprintf(stderr,
                         "usage: bench_pane_split [--methods est,full] [--surface-seeds] [--scenes DIR]\n");
            return 2;
        }
    }
    setLogLevel(LogLevel::Warning);
    try {
        std::printf("window_pane over %d steps (0.2 s)%s\n", kSteps,
                    surfaceSeeds ? "; FULL with surface-breaking seeds" : "");
        std::printf("%-6s %6s %8s %7s %7s %8s\n", "method", "speed", "largest", "pieces", "events", "wall_s");
        for (const FractureMethod method : methods) {
            const bool seeds = surfaceSeeds && method == FractureMethod::Full;
            const std::string name = std::string(toString(method)) + (seeds ? "_surface_seeds" : "");
            double worst = 0.0;
            for (const double speed : kSpeeds) {
                const Split s = run(scenes, method, seeds, speed);
                worst = std::max(worst, s.largestShare);
                std::printf("%-6s %6.2f %8.3f %7d %7d %8.1f\n", name.c_str(), speed, s.largestShare, s.pieces,
                            s.events, s.seconds);
                std::printf("METRIC window_pane_largest_piece_%s_%s %.3f ratio\n", name.c_str(),
                            speedTag(speed).c_str(), s.largestShare);
                std::fflush(stdout);
            }
            std::printf("METRIC window_pane_largest_piece_%s_worst %.3f ratio (goal <= 0.5)\n", name.c_str(),
                        worst);
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_pane_split: %s\n", e.what());
        return 1;
    }
    return 0;
}
