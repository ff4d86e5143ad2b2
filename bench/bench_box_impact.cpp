// SPDX-License-Identifier: Zlib
// Large crack systems in a rigid-body scene: bench/scenes/box_impact.json (a free 1 m PMMA-like
// box hit by a 650 kg ball of radius 0.25 m at 20 m/s, 60 steps of 4 ms) at 500 and 1,500 BEM triangles, with
// FULL, EST and HYBRID (switching at 2,000 BEM elements). Each run is a child process (IsolatedRun.h), so its
// peak memory is its own, under an address-space limit so that a run which grows too large fails alone. Per
// run: the fracture events (engine calls that returned fragments), the wall time of each event's
// FractureEngine::fracture() call (FractureEventInfo::engineSeconds), the crack triangles in the parent's BEM
// after each event, and the engine calls that broke nothing.
//   bench_box_impact [--quick] [--triangles 500,1500] [--methods full,est,hybrid] [--memory-limit MB]
// --quick: 500 triangles only (about a minute; all six runs 11-20 minutes on 2 cores).
#include "IsolatedRun.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

const std::string kSceneFile = std::string(BTFRACTURE_BENCH_DIR) + "/scenes/box_impact.json";
constexpr int kHybridThreshold = 2000;  // BEM elements (surface + crack) at which HYBRID switches to EST

struct Event {
    double engineSeconds = 0.0;  // wall time of the FractureEngine::fracture() call that broke the body
    int crackTriangles = 0;      // crack triangles in the parent's BEM after the event
    int fragments = 0;
    EngineTimings timings;  // the engine's split of engineSeconds
};

struct BoxRun {
    std::vector<Event> events;
    int idleCalls = 0;         // engine calls that returned no fragments
    double idleSeconds = 0.0;  // wall time of the frames with such calls and no event
    double wallSeconds = 0.0;  // all 60 frames
};

struct EventLog : FractureListener {
    std::vector<Event> events;
    void onFractureEvent(btFractureRigidBody&, const std::vector<btFractureRigidBody*>& pieces,
                         const FractureEventInfo& info) override {
        events.push_back(
            {info.engineSeconds, info.crackTriangles, static_cast<int>(pieces.size()), info.engineTimings});
    }
};

std::string serialize(const BoxRun& r) {
    std::ostringstream out;
    out.precision(17);
    out << "idle " << r.idleCalls << ' ' << r.idleSeconds << "\nwall " << r.wallSeconds << '\n';
    for (const Event& e : r.events)
        out << "event " << e.engineSeconds << ' ' << e.crackTriangles << ' ' << e.fragments << ' '
            << e.timings.bem << ' ' << e.timings.fracture << ' ' << e.timings.geometry << '\n';
    return out.str();
}

BoxRun deserialize(const std::string& text) {
    BoxRun r;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
        if (word == "idle") {
            in >> r.idleCalls >> r.idleSeconds;
        } else if (word == "wall") {
            in >> r.wallSeconds;
        } else if (word == "event") {
            Event e;
            in >> e.engineSeconds >> e.crackTriangles >> e.fragments >> e.timings.bem >> e.timings.fracture >>
                e.timings.geometry;
            r.events.push_back(e);
        } else {
            throw Error("bench_box_impact: unexpected word '" + word + "' in a run's result");
        }
    }
    return r;
}

// The scene as users run it (btfracture-run bench/scenes/box_impact.json), with the box's BEM
// resolution and method set for this run.
BoxRun runBox(int triangles, FractureMethod method) {
    setLogLevel(LogLevel::Warning);
    Scene scene = readSceneFile(kSceneFile);
    overrideFractureMethod(scene, method);
    for (SceneBody& b : scene.bodies)
        if (b.fracture.fracturable) {
            b.fracture.bemTriangleTarget = triangles;
            b.fracture.hybridElementThreshold = kHybridThreshold;
        }
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    auto& fractureWorld = dynamic_cast<btFractureDynamicsWorld&>(world.world());
    EventLog log;
    fractureWorld.addFractureListener(&log);
    BoxRun r;
    for (int f = 0; f < scene.world.steps; ++f) {
        const FractureStatistics before = fractureWorld.fractureStatistics();
        const std::size_t eventsBefore = log.events.size();
        Timer timer;
        world.stepFrame();
        const double seconds = timer.seconds();
        r.wallSeconds += seconds;
        const FractureStatistics& after = fractureWorld.fractureStatistics();
        const auto idle = static_cast<int>((after.engineCalls - before.engineCalls) -
                                           (after.fractureEvents - before.fractureEvents));
        r.idleCalls += idle;
        if (idle > 0 && log.events.size() == eventsBefore) r.idleSeconds += seconds;
    }
    fractureWorld.removeFractureListener(&log);
    r.events = log.events;
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> split(const std::string& list) {
    std::vector<std::string> out;
    std::istringstream in(list);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "bench_box_impact: %s\nusage: bench_box_impact [--quick] [--triangles 500,1500] "
                 "[--methods full,est,hybrid] [--memory-limit MB]\n",
                 problem.c_str());
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> sizes{500, 1500};
    std::vector<FractureMethod> methods{FractureMethod::Full, FractureMethod::Estimated,
                                        FractureMethod::Hybrid};
    double memoryLimit = 6144.0;  // [MB] per run; FULL at 1,500 triangles needs a few GB
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--quick") {
            sizes = {500};
        } else if (arg == "--triangles") {
            sizes.clear();
            for (const std::string& s : split(value())) {
                char* end = nullptr;
                const long n = std::strtol(s.c_str(), &end, 10);
                if (*end != '\0' || n < 4 || n > 1000000)
                    usage("--triangles: '" + s + "' is not a triangle count >= 4");
                sizes.push_back(static_cast<int>(n));
            }
            if (sizes.empty()) usage("--triangles: empty list");
        } else if (arg == "--methods") {
            methods.clear();
            for (const std::string& s : split(value())) {
                try {
                    methods.push_back(parseFractureMethod(s, "--methods"));
                } catch (const Error& e) {
                    usage(e.what());
                }
            }
            if (methods.empty()) usage("--methods: empty list");
        } else if (arg == "--memory-limit") {
            const std::string s = value();
            char* end = nullptr;
            memoryLimit = std::strtod(s.c_str(), &end);
            if (*end != '\0' || !(memoryLimit > 0.0))
                usage("--memory-limit: '" + s + "' is not a positive number of MB");
        } else {
            usage("unknown argument '" + arg + "'");
        }
    }

    // first_s is split into the first event's BEM (remesh, assembly, solves), crack (SIFs,
    // initiation, propagation: where FULL and EST differ) and geometry (cuts, fragments) time;
    // engine_s sums every engine call, wall_s all 60 frames; cpu_s is the run's CPU time (all
    // threads), which a shared machine does not inflate the way it inflates wall times.
    std::printf("%6s %-6s %6s %6s %8s %8s %8s %8s %9s %11s %9s %8s %9s %8s %8s\n", "tris", "method", "events",
                "calls", "first_s", "bem_s", "crack_s", "geom_s", "median_s", "crack_tris", "frags_1st",
                "peak_MB", "engine_s", "wall_s", "cpu_s");
    bool failed = false;
    for (int tris : sizes) {
        for (FractureMethod method : methods) {
            const IsolatedRun child =
                runIsolated([&] { return serialize(runBox(tris, method)); }, memoryLimit);
            const std::string name = "box_" + std::to_string(tris) + "_" + toString(method);
            if (!child.ok) {
                failed = true;
                std::printf("%6d %-6s FAILED after %.0f MB peak: %s\n", tris, toString(method),
                            child.peakMegabytes, child.failure.c_str());
                continue;
            }
            const BoxRun r = deserialize(child.text);
            std::vector<double> seconds;
            int crackMin = 0, crackMax = 0;
            double engine = r.idleSeconds;
            for (const Event& e : r.events) {
                seconds.push_back(e.engineSeconds);
                engine += e.engineSeconds;
                crackMin = seconds.size() == 1 ? e.crackTriangles : std::min(crackMin, e.crackTriangles);
                crackMax = std::max(crackMax, e.crackTriangles);
            }
            const int events = static_cast<int>(r.events.size());
            const double first = events > 0 ? seconds.front() : 0.0;
            const double med = events > 0 ? median(seconds) : 0.0;
            const std::string crack = std::to_string(crackMin) + "-" + std::to_string(crackMax);
            const Event firstEvent = events > 0 ? r.events.front() : Event{};
            std::printf("%6d %-6s %6d %6d %8.2f %8.2f %8.2f %8.2f %9.2f %11s %9d %8.0f %9.2f %8.2f %8.2f\n",
                        tris, toString(method), events, events + r.idleCalls, first, firstEvent.timings.bem,
                        firstEvent.timings.fracture, firstEvent.timings.geometry, med, crack.c_str(),
                        firstEvent.fragments, child.peakMegabytes, engine, r.wallSeconds, child.cpuSeconds);
            std::printf("METRIC %s_events %d count\n", name.c_str(), events);
            if (events > 0) {
                std::printf("METRIC %s_first_event_s %.3f s\n", name.c_str(), first);
                std::printf("METRIC %s_median_event_s %.3f s\n", name.c_str(), med);
                std::printf("METRIC %s_crack_triangles_min %d triangles\n", name.c_str(), crackMin);
                std::printf("METRIC %s_crack_triangles_max %d triangles\n", name.c_str(), crackMax);
            }
            std::printf("METRIC %s_peak_memory_MB %.0f MB\n", name.c_str(), child.peakMegabytes);
            std::fflush(stdout);
        }
    }
    return failed ? 1 : 0;
}
