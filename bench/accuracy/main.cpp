// SPDX-License-Identifier: Zlib
// Accuracy against time: every case runs with FULL, EST and - where cracks grow -
// HYBRID at three thresholds (the surface plus 25 / 50 / 75 % of the crack triangles FULL
// ended with, §4.4). Each run is a child process (peak memory per run). Writes runs.csv,
// steps.csv and table.md into --out (make bench-accuracy then draws the charts with
// scripts/charts/accuracy_charts.py), and prints METRIC lines.
//   accuracy_vs_time [--out DIR] [--smoke] [--frames N] [--cases a,b,...] [--methods FULL,EST,...]
//   [--gain-limit X] [--crack-refinement K] [--cpu-limit S] [--verbose]
// --cpu-limit S: each run's CPU time cap [s] (default 900; 0: none); a run over it is a failed row.
// --crack-refinement K: the solver cases with crack elements K times finer (SolverCases.h).
// --smoke: penny, inclined penny and the mode-I growth test, FULL and EST only; exits non-zero when EST's
// mode-I SIF error exceeds 15 % or FULL's penny K_I is off by more than 3 %.
#include "IsolatedRun.h"  // bench/
#include "Report.h"
#include "SceneCases.h"
#include "SolverCases.h"
#include "SurfaceDistance.h"

#include <btFracture/core/Log.h>
#include <btFracture/core/Timer.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace accuracy;
using btfracture::FractureMethod;

namespace {

bool selected(const std::string& filter, const std::string& name) {
    return filter.empty() || ("," + filter + ",").find("," + name + ",") != std::string::npos;
}

void print(const RunResult& r) {
    std::printf(
        "  %-20s %-8s thr %5d  crack %6d  steps %3d  events %2d  fracture %8.3f s  engine %8.3f s  rigid "
        "%7.3f s  %6.0f "
        "MB"
        "  sif %6.1f %%  surf %6.2f %%  frag %4d  mott %5.2f  %s\n",
        r.caseName.c_str(), r.method.c_str(), r.threshold, r.crackTriangles, r.steps, r.events,
        r.fractureSeconds, r.engineSeconds(), r.rigidSeconds, r.peakMegabytes,
        r.sifError < 0 ? -1.0 : 100 * r.sifError, r.surfaceMean < 0 ? -1.0 : 100 * r.surfaceMean, r.fragments,
        r.mottKs, r.note.c_str());
    std::fflush(stdout);
}

double cpuLimitSeconds = 900.0;  // --cpu-limit

// `run` in a child process (IsolatedRun.h); its result with the child's peak memory, or a result
// whose note says why the run failed.
RunResult runInChild(const std::function<RunResult()>& run, const std::string& caseName,
                     const std::string& method) {
    const btfracture::IsolatedRun child =
        btfracture::runIsolated([&] { return serialize(run()); }, 0.0, cpuLimitSeconds);
    RunResult r;
    if (child.ok) {
        r = deserialize(child.text);
    } else {
        std::fprintf(stderr, "accuracy: %s / %s failed: %s\n", caseName.c_str(), method.c_str(),
                     child.failure.c_str());
        r.caseName = caseName;
        r.method = method;
        r.note = "run failed (" + child.failure + ")";
    }
    r.peakMegabytes = child.peakMegabytes;
    return r;
}

// FULL first (the reference), then EST, then the three HYBRID thresholds when `grows` and FULL
// gave its crack triangles.
std::string methodFilter;  // --methods: run only these (FULL is still the reference when run)

std::vector<RunResult> runMethods(const std::string& name, bool grows, int surface,
                                  const std::function<RunResult(const MethodChoice&)>& run) {
    std::vector<RunResult> out;
    auto go = [&](const MethodChoice& m) {
        if (!selected(methodFilter, m.label)) return;
        out.push_back(runInChild([&] { return run(m); }, name, m.label));
        std::printf("  %s %s done\n", name.c_str(), m.label.c_str());
        std::fflush(stdout);
    };
    go({"FULL", FractureMethod::Full, 0});
    go({"EST", FractureMethod::Estimated, 0});
    if (grows && !out.empty() && !out[0].failed()) {
        const int s = out[0].surfaceTriangles > 0 ? out[0].surfaceTriangles : surface;
        for (int percent : {25, 50, 75}) {
            const int threshold = s + std::max(1, out[0].crackTriangles * percent / 100);
            go({"HYB-" + std::to_string(percent), FractureMethod::Hybrid, threshold});
        }
    }
    // Fracture surface against FULL's, relative to the body size.
    if (out.empty()) return out;
    for (auto& r : out) {
        const SurfaceDistance d = surfaceDistance(r.surface, out[0].surface);
        const double size = out[0].bodySize > 0.0 ? out[0].bodySize : 1.0;
        if (d.mean >= 0.0) r.surfaceMean = d.mean / size, r.surfaceHausdorff = d.hausdorff / size;
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string outDir = "out/accuracy", filter;
    bool smoke = false;
    int frames = 60;          // 0.24 s: the ball hits at about frame 15
    double gainLimit = -1.0;  // --gain-limit: EST's §4.3 update gain limit in the scenes (0: off)
    int refinement = 1;       // --crack-refinement: crack elements k times finer in the solver cases
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--smoke"))
            smoke = true;
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            outDir = argv[++i];
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--cases") && i + 1 < argc)
            filter = argv[++i];
        else if (!std::strcmp(argv[i], "--gain-limit") && i + 1 < argc)
            gainLimit = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--crack-refinement") && i + 1 < argc && std::atoi(argv[i + 1]) >= 1)
            refinement = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--methods") && i + 1 < argc)
            methodFilter = argv[++i];
        else if (!std::strcmp(argv[i], "--cpu-limit") && i + 1 < argc && std::atof(argv[i + 1]) >= 0.0)
            cpuLimitSeconds = std::atof(argv[++i]);
        else if (!std::strcmp(argv[i], "--verbose"))  // per-step fracture log (debug level)
            btfracture::setLogLevel(btfracture::LogLevel::Debug);
        else {
            std::fprintf(
                stderr,
                "usage: %s [--out DIR] [--smoke] [--frames N] [--cases a,b,...] [--methods "
                "FULL,EST,...] [--gain-limit X] [--crack-refinement K] [--cpu-limit S] [--verbose]\n",
                argv[0]);
            return 2;
        }
    }
    ::mkdir(outDir.c_str(), 0755);
    btfracture::Timer total;
    std::vector<RunResult> runs;
    for (const SolverCaseInfo& c : solverCases(smoke)) {
        if (!selected(filter, c.name)) continue;
        std::printf("%s\n", c.name.c_str());
        auto results = runMethods(c.name, c.grows && !smoke, 0, [&](const MethodChoice& m) {
            return runSolverCase(c.name, m, smoke, refinement);
        });
        if (!c.analytic)
            for (auto& r : results)
                r.sifError = results.empty() ? -1.0 : compareWithReference(c.name, r, results[0]);
        else
            for (auto& r : results)
                r.surfaceMean = r.surfaceHausdorff = -1.0;  // no growth: nothing to compare
        for (const auto& r : results) print(r);
        runs.insert(runs.end(), results.begin(), results.end());
    }
    for (const SceneCaseInfo& c : sceneCases(smoke)) {
        if (!selected(filter, c.name)) continue;
        std::printf("%s\n", c.name.c_str());
        auto results = runMethods(c.name, c.hybrids, c.bemTriangles, [&](const MethodChoice& m) {
            return runSceneCase(c, m, frames, gainLimit);
        });
        for (const auto& r : results) print(r);
        runs.insert(runs.end(), results.begin(), results.end());
    }

    writeRunsCsv(outDir + "/runs.csv", runs);
    writeStepsCsv(outDir + "/steps.csv", runs);
    writeMarkdownTable(outDir + "/table.md", runs);

    auto find = [&](const std::string& name, const std::string& method) -> const RunResult* {
        for (const auto& r : runs)
            if (r.caseName == name && r.method == method) return &r;
        return nullptr;
    };
    int status = 0;
    if (const RunResult* est = find("mode_I_growth", "EST")) {
        std::printf("METRIC est_sif_error_mode1 %.4f relative (goal <= 0.15)\n", est->sifError);
        if (smoke && !(est->sifError >= 0.0 && est->sifError <= 0.15)) status = 1;
    }
    if (const RunResult* full = find("penny", "FULL"))
        if (smoke && !(full->sifError >= 0.0 && full->sifError <= 0.03)) status = 1;
    const RunResult *full = find("bunny_weak_1000", "FULL"), *est = find("bunny_weak_1000", "EST");
    if (full && est && est->engineSeconds() > 0.0) {
        std::printf(
            "METRIC est_speedup_many_fragments %.3f ratio (FULL %.2f s / EST %.2f s in the engine; "
            "crack propagation only: %.2f s / %.2f s; events %d / %d; first event alone: %.2f s / %.2f s; "
            "fragments of the first event %d / %d; goal >= 50)\n",
            full->engineSeconds() / est->engineSeconds(), full->engineSeconds(), est->engineSeconds(),
            full->fractureSeconds, est->fractureSeconds, full->events, est->events, full->firstEventSeconds,
            est->firstEventSeconds, full->fragments, est->fragments);
    }
    std::printf("many-fragment bunny, FULL / EST engine time by BEM resolution:");
    for (int triangles : {750, 1000, 1500, 2000}) {
        const std::string name = "bunny_weak_" + std::to_string(triangles);
        const RunResult *f = find(name, "FULL"), *e = find(name, "EST");
        if (f && e && f->engineSeconds() > 0.0 && e->engineSeconds() > 0.0)
            std::printf("  %d: %.1fx (%.1f / %.1f s, events %d / %d)", triangles,
                        f->engineSeconds() / e->engineSeconds(), f->engineSeconds(), e->engineSeconds(),
                        f->events, e->events);
    }
    std::printf("\n");
    std::printf("METRIC accuracy_study_wall_s %.1f s (%zu runs)\n", total.seconds(), runs.size());
    return status;
}
