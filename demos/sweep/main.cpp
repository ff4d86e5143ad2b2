// SPDX-License-Identifier: Zlib
// btfracture-sweep: many seeded impact runs of one scene (a sweep file, io/SweepFile.h), split
// into shards for GNU parallel or a Slurm job array, resumable; --collect gathers one index CSV.
//
// Each run is a child process (this program again, --run-one I), so that a crash or a kill ends
// one run only and every run starts from a fresh process; the parent skips finished runs, starts
// up to --jobs children, and records a run whose child died without a result.
//
// Exit codes: 0 every run of the share finished (or had finished), 1 internal failure, 2 bad input
// (command line, sweep file, base scene), 4 some runs of the share failed (recorded in their run.json).
#include "ImpactRecorder.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ThreadLimit.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/io/AtomicFile.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/RunRecord.h>
#include <btFracture/io/SceneFractureListener.h>
#include <btFracture/io/SceneWorld.h>
#include <btFracture/io/Sha256.h>
#include <btFracture/io/StatisticsCsv.h>
#include <btFracture/io/SweepFile.h>

#include <btBulletDynamicsCommon.h>
#include <nlohmann/json.hpp>

#include "RunnerVersion.h"  // generated: BTFRACTURE_VERSION, BTFRACTURE_SOURCE_REVISION

#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace btfracture;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

enum ExitCode { kSuccess = 0, kInternalFailure = 1, kBadInput = 2, kNonFinite = 3, kRunsFailed = 4 };

const char* kUsage =
    "usage: btfracture-sweep SWEEP --out DIR [--shard k/K | --runs a-b] [--jobs J] [--threads T]\n"
    "                        [--max-attempts N] [--retry-failed] [--list]\n"
    "       btfracture-sweep --collect DIR\n";

const char* kHelp =
    "Runs its share of a sweep (SWEEP: a sweep file, format in demos/README.md) into DIR, one folder\n"
    "run_NNNNNN per run:\n"
    "  run.json         the run's parameters, outcome (status done or failed, exit status, error),\n"
    "                   fracture events, fragments and impact summary; written last, atomically:\n"
    "                   a folder without it is unfinished\n"
    "  fragments.obj    the target's final pieces in its rest frame, where they came from\n"
    "  fragments.csv, fragment_volumes.csv   piece volumes (when the target broke)\n"
    "  statistics.csv   one row per fracture event (wall-time columns empty)\n"
    "  contacts.csv     impactor-target contacts per step: rest-frame point, normal, impulse\n"
    "  timing.json      host, start and end, wall time per phase, CPU time, peak memory (the\n"
    "                   one file that differs between two runs of the same sweep)\n"
    "  attempts         how often the run was started\n"
    "\n"
    "  --shard k/K      runs [k N / K, (k + 1) N / K) of the N runs (0 <= k < K)\n"
    "  --runs a-b       runs a to b inclusive (default: all)\n"
    "  --jobs J         runs at once (default 1)\n"
    "  --threads T      worker threads per run (default 1)\n"
    "  --max-attempts N starts of a run that ended without a result (killed, crashed) before it is\n"
    "                   recorded as failed (default 3)\n"
    "  --retry-failed   run again the runs recorded as failed\n"
    "  --list           print the run numbers of the share and exit\n"
    "  --collect DIR    write DIR/index.csv over every finished run\n"
    "\n"
    "Finished runs (done or failed) are skipped, unfinished folders cleared and run again. Run i\n"
    "depends on the sweep file and i only: any shard layout gives the same files (timing.json and\n"
    "attempts aside).\n"
    "Exit status: 0 every run of the share finished, 1 internal failure, 2 bad input, 4 some runs\n"
    "failed (see their run.json).\n";

struct Options {
    std::string sweep;
    std::string out;
    int first = 0, last = -1;  // inclusive; last -1: to the end
    std::optional<std::pair<int, int>> shard;
    int jobs = 1, threads = 1, maxAttempts = 3;
    bool retryFailed = false, list = false;
    std::optional<int> runOne;  // internal: the child's run
    std::string collect;
};

int integer(const std::string& option, const std::string& text, int minimum) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < minimum || value > 1000000000)
        throw Error(option + " expects an integer >= " + std::to_string(minimum) + ", got '" + text + "'");
    return static_cast<int>(value);
}

std::pair<int, int> pairOf(const std::string& option, const std::string& text, char separator) {
    const size_t at = text.find(separator);
    if (at == std::string::npos)
        throw Error(option + " expects " + (separator == '/' ? "k/K" : "a-b") + ", got '" + text + "'");
    return {integer(option, text.substr(0, at), 0), integer(option, text.substr(at + 1), 0)};
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() {
            if (i + 1 >= argc) throw Error(arg + " needs a value");
            return std::string(argv[++i]);
        };
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            std::fputs(kHelp, stdout);
            std::exit(kSuccess);
        } else if (arg == "--out") {
            o.out = value();
        } else if (arg == "--shard") {
            o.shard = pairOf(arg, value(), '/');
        } else if (arg == "--runs") {
            std::tie(o.first, o.last) = pairOf(arg, value(), '-');
            if (o.last < o.first) throw Error("--runs a-b needs a <= b");
        } else if (arg == "--jobs") {
            o.jobs = integer(arg, value(), 1);
        } else if (arg == "--threads") {
            o.threads = integer(arg, value(), 0);
        } else if (arg == "--max-attempts") {
            o.maxAttempts = integer(arg, value(), 1);
        } else if (arg == "--retry-failed") {
            o.retryFailed = true;
        } else if (arg == "--list") {
            o.list = true;
        } else if (arg == "--collect") {
            o.collect = value();
        } else if (arg == "--run-one") {
            o.runOne = integer(arg, value(), 0);
        } else if (!arg.empty() && arg[0] == '-') {
            throw Error("unknown option '" + arg + "'");
        } else if (o.sweep.empty()) {
            o.sweep = arg;
        } else {
            throw Error("more than one sweep file given ('" + o.sweep + "', '" + arg + "')");
        }
    }
    if (!o.collect.empty()) return o;
    if (o.sweep.empty()) throw Error("no sweep file given");
    if (o.out.empty() && !o.list) throw Error("--out DIR is required");
    if (o.shard && o.last >= 0) throw Error("give --shard or --runs, not both");
    return o;
}

std::string runFolderName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "run_%06d", index);
    return name;
}

Json vectorJson(const Eigen::Vector3d& v) {
    return Json::array({v.x(), v.y(), v.z()});
}

// The run's parameters as run.json and the index give them.
Json parametersJson(const SweepRunParameters& p) {
    const Eigen::Quaterniond& q = p.targetOrientation;
    Json j;
    j["speed_mps"] = p.speed;
    j["direction"] = vectorJson(p.direction);
    j["impact_point_rest"] = vectorJson(p.pointRest);
    j["impact_normal_rest"] = vectorJson(p.normalRest);
    j["impact_point_world"] = vectorJson(p.pointWorld);
    j["impactor_scale"] = p.impactorScale;
    j["impactor_mass_kg"] = p.impactorMass ? Json(*p.impactorMass) : Json(nullptr);
    j["target_orientation_wxyz"] = Json::array({q.w(), q.x(), q.y(), q.z()});
    j["seed"] = p.seed;
    j["method"] = toString(p.method);
    return j;
}

struct Outcome {
    std::string status = "done";  // or "failed"
    int exitStatus = kSuccess;
    std::string error;
    int stepsTaken = 0, fractureEvents = 0, fragments = 0;
    Json impact = Json::object();
};

// run.json: everything here is the same whichever machine, shard or attempt made it.
void writeRunJson(const fs::path& dir, const SweepSpec& spec, const SweepRunParameters& p, const Outcome& o) {
    Json j;
    j["program"] = "btfracture-sweep";
    j["version"] = BTFRACTURE_VERSION;
    j["source_revision"] = BTFRACTURE_SOURCE_REVISION;
    j["sweep"] = {{"file", fs::path(spec.file).filename().string()}, {"sha256", sha256OfFile(spec.file)}};
    j["base_scene"] = {{"file", fs::path(spec.sceneFile).filename().string()},
                       {"sha256", sha256OfFile(spec.sceneFile)}};
    j["run"] = p.index;
    j["parameters"] = parametersJson(p);
    j["status"] = o.status;
    j["exit_status"] = o.exitStatus;
    j["error"] = o.error;
    j["steps_taken"] = o.stepsTaken;
    j["fracture_events"] = o.fractureEvents;
    j["fragments"] = o.fragments;
    j["impact"] = o.impact;
    writeFileAtomically((dir / "run.json").string(), j.dump(2) + "\n");
}

// Linux reports kilobytes.
double peakMemoryMegabytes(const rusage& usage) {
    return usage.ru_maxrss / 1024.0;
}

double cpuSeconds(const rusage& usage) {
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

std::string hostName() {
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return name;
}

// Contact episodes: runs of consecutive steps with impactor-target contact. Times are those of
// contacts.csv: the end of the step whose solve applied the impulse.
Json impactSummary(const ImpactRecorder& impacts) {
    const auto& contacts = impacts.contacts();
    const double h = impacts.stepLength();
    Json j;
    j["contact_points"] = contacts.size();
    if (contacts.empty()) return j;
    double total = 0.0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    std::map<long, double> perStep;
    for (const auto& c : contacts) {
        total += c.impulse;
        point += c.impulse * c.point;
        normal += c.impulse * c.normal;
        perStep[c.step] += c.impulse;
    }
    Json episodes = Json::array();
    long start = -1, previous = -2;
    double impulse = 0.0, peak = 0.0;
    const auto close = [&] {
        if (start >= 0)
            episodes.push_back({{"start_s", start * h},
                                {"duration_s", (previous - start + 1) * h},
                                {"impulse_Ns", impulse}});
    };
    for (const auto& [step, stepImpulse] : perStep) {
        if (step != previous + 1) {
            close();
            start = step;
            impulse = 0.0;
        }
        impulse += stepImpulse;
        peak = std::max(peak, stepImpulse);
        previous = step;
    }
    close();
    j["first_contact_s"] = perStep.begin()->first * h;
    j["total_impulse_Ns"] = total;
    j["peak_step_impulse_Ns"] = peak;
    j["mean_point_rest"] = vectorJson(point / total);
    j["mean_normal_rest"] = vectorJson(normal.normalized());
    j["episodes"] = episodes;
    return j;
}

// The child: one run into `dir` (already cleared by the parent). Writes run.json last.
int runOne(const Options& options, const SweepSpec& spec, int index) {
    Timer total;
    const std::string start = utcTimestamp(std::chrono::system_clock::now());
    const fs::path dir = fs::path(options.out) / runFolderName(index);
    const SweepRunBuilder builder(spec);
    const SweepRunParameters parameters = builder.parameters(index);
    Scene scene = builder.scene(parameters);
    scene.run.threads = options.threads;
    const ThreadLimit threads(options.threads);

    Outcome outcome;
    double setupSeconds = 0.0, stepSeconds = 0.0, fractureSeconds = 0.0, outputSeconds = 0.0;
    try {
        FractureSceneWorldFactory factory(scene.effects.seed);
        SceneWorld world(scene, factory);
        auto& fractureWorld = dynamic_cast<btFractureDynamicsWorld&>(world.world());
        FractureRecorder recorder((dir / "statistics.csv").string(), false);
        FractureRecorderListener recorderListener(recorder, scene.world.dt / scene.world.substeps);
        const btRigidBody *target = nullptr, *impactor = nullptr;
        for (const auto& body : world.bodies()) {
            if (body.name == spec.target) target = body.rigidBody;
            if (body.name == spec.impactor) impactor = body.rigidBody;
        }
        SceneFractureListener sceneListener(recorderListener, world);
        ImpactRecorder impacts(world, *target, *impactor, builder.targetRestToWorld(parameters));
        fractureWorld.addFractureListener(&sceneListener);
        fractureWorld.addFractureListener(&impacts);
        setupSeconds = total.seconds();

        for (int step = 1; step <= scene.world.steps; ++step) {
            Timer timer;
            world.stepFrame();
            stepSeconds += timer.seconds();
            outcome.stepsTaken = step;
            if (const SceneWorld::Body* body = world.firstNonFiniteBody())
                outcome.error = "body '" + body->name + "' became non-finite (NaN or Inf) at step " +
                                std::to_string(step);
            if (!outcome.error.empty()) break;
        }
        fractureWorld.finishEnergyAudits();
        impacts.finish();
        Timer output;
        recorder.close();
        recorder.writeFragmentVolumes((dir / "fragment_volumes.csv").string(),
                                      (dir / "fragments.csv").string());
        ObjWriter pieces((dir / "fragments.obj").string());
        for (const auto& body : world.bodies())
            if (const Eigen::Isometry3d* toRest = impacts.restFrameOf(body.rigidBody)) {
                TriangleMesh mesh = body.surface;
                for (Eigen::Vector3d& v : mesh.vertices) v = *toRest * v;
                pieces.addObject(body.name, mesh);
                ++outcome.fragments;
            }
        pieces.close();
        impacts.writeCsv((dir / "contacts.csv").string());
        outcome.fractureEvents = recorder.events();
        outcome.impact = impactSummary(impacts);
        fractureSeconds = fractureWorld.fractureStatistics().fractureSeconds();
        outputSeconds = output.seconds();
        if (!outcome.error.empty()) {
            outcome.status = "failed";
            outcome.exitStatus = kNonFinite;
        }
    } catch (const std::exception& e) {
        outcome.status = "failed";
        outcome.exitStatus = kInternalFailure;
        outcome.error = std::string("internal failure: ") + e.what();
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const Json timing = {{"host", hostName()},
                         {"start", start},
                         {"end", utcTimestamp(std::chrono::system_clock::now())},
                         {"seconds",
                          {{"setup", setupSeconds},
                           {"rigid_body", stepSeconds - fractureSeconds},
                           {"fracture", fractureSeconds},
                           {"output", outputSeconds},
                           {"total", total.seconds()}}},
                         {"cpu_seconds", cpuSeconds(usage)},
                         {"threads", options.threads},
                         {"peak_memory_mb", peakMemoryMegabytes(usage)}};
    writeFileAtomically((dir / "timing.json").string(), timing.dump(2) + "\n");
    writeRunJson(dir, spec, parameters, outcome);
    if (outcome.exitStatus != kSuccess)
        std::fprintf(stderr, "btfracture-sweep: run %d failed: %s\n", index, outcome.error.c_str());
    return outcome.exitStatus;
}

// "done", "failed", or empty for a run without run.json.
std::string finishedStatus(const fs::path& dir) {
    std::ifstream in(dir / "run.json");
    if (!in) return "";
    try {
        return Json::parse(in).value("status", "");
    } catch (const Json::exception&) {
        return "";  // cannot happen for an atomically written file; treat as unfinished
    }
}

int readAttempts(const fs::path& dir) {
    std::ifstream in(dir / "attempts");
    int attempts = 0;
    in >> attempts;
    return attempts;
}

// Empties an unfinished folder (but its attempt count) and counts this attempt.
void startAttempt(const fs::path& dir, int attempt) {
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename() != "attempts") fs::remove_all(entry.path());
    writeFileAtomically((dir / "attempts").string(), std::to_string(attempt) + "\n");
}

std::vector<int> shareOf(const Options& o, const SweepSpec& spec) {
    int first = 0, last = spec.runs;  // [first, last)
    if (o.shard) {
        std::tie(first, last) = shardRuns(spec.runs, o.shard->first, o.shard->second);
    } else if (o.last >= 0) {
        if (o.last >= spec.runs)
            throw Error("--runs " + std::to_string(o.first) + "-" + std::to_string(o.last) +
                        ": the sweep has runs 0-" + std::to_string(spec.runs - 1));
        first = o.first;
        last = o.last + 1;
    }
    std::vector<int> runs;
    for (int i = first; i < last; ++i) runs.push_back(i);
    return runs;
}

int runShare(const Options& o, const SweepSpec& spec, const SweepRunBuilder& builder, const char* self) {
    const std::vector<int> runs = shareOf(o, spec);
    fs::create_directories(o.out);
    std::vector<int> todo;
    int skipped = 0, failed = 0;
    for (int index : runs) {
        const fs::path dir = fs::path(o.out) / runFolderName(index);
        const std::string status = finishedStatus(dir);
        if (status == "done" || (status == "failed" && !o.retryFailed)) {
            ++skipped;
            failed += status == "failed" ? 1 : 0;
            continue;
        }
        todo.push_back(index);
    }
    logf(LogLevel::Info, "btfracture-sweep: ", runs.size(), " runs in this share, ", skipped,
         " finished before, ", todo.size(), " to do with ", o.jobs, " jobs");

    std::map<pid_t, int> running;  // child -> run
    size_t next = 0;
    const auto record = [&](int index, const std::string& error, int exitStatus) {
        Outcome outcome;
        outcome.status = "failed";
        outcome.exitStatus = exitStatus;
        outcome.error = error;
        writeRunJson(fs::path(o.out) / runFolderName(index), spec, builder.parameters(index), outcome);
        ++failed;
        std::fprintf(stderr, "btfracture-sweep: run %d failed: %s\n", index, error.c_str());
    };
    while (next < todo.size() || !running.empty()) {
        while (next < todo.size() && static_cast<int>(running.size()) < o.jobs) {
            const int index = todo[next++];
            const fs::path dir = fs::path(o.out) / runFolderName(index);
            const int attempt = readAttempts(dir) + 1;
            if (attempt > o.maxAttempts) {
                record(index, "gave up: " + std::to_string(attempt - 1) + " attempts ended without a result",
                       kInternalFailure);
                continue;
            }
            startAttempt(dir, attempt);
            const std::vector<std::string> args = {self,        o.sweep,
                                                   "--out",     o.out,
                                                   "--run-one", std::to_string(index),
                                                   "--threads", std::to_string(o.threads)};
            std::fflush(nullptr);
            const pid_t child = fork();
            if (child < 0) throw Error("cannot start a run: fork failed");
            if (child == 0) {
                prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed sweep takes its runs along
                std::vector<char*> argv;
                for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
                argv.push_back(nullptr);
                execv("/proc/self/exe", argv.data());
                _exit(127);
            }
            running[child] = index;
        }
        int status = 0;
        rusage usage{};
        const pid_t done = wait4(-1, &status, 0, &usage);
        if (done < 0) throw Error("waiting for runs failed");
        const auto it = running.find(done);
        if (it == running.end()) continue;
        const int index = it->second;
        running.erase(it);
        const std::string finished = finishedStatus(fs::path(o.out) / runFolderName(index));
        if (finished == "failed")
            ++failed;
        else if (finished.empty())
            record(index,
                   WIFSIGNALED(status)
                       ? "killed by signal " + std::to_string(WTERMSIG(status))
                       : "exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result",
                   WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status));
        logf(LogLevel::Info, "btfracture-sweep: run ", index, " ", finished.empty() ? "failed" : finished,
             " (", peakMemoryMegabytes(usage), " MB peak)");
    }
    return failed > 0 ? kRunsFailed : kSuccess;
}

std::string csvNumber(const Json& value) {
    if (value.is_null()) return "";
    if (value.is_number_float()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", value.get<double>());
        return text;
    }
    return value.is_string() ? csvField(value.get<std::string>()) : value.dump();
}

// DIR/index.csv over the run folders that have run.json, in run order.
int collect(const std::string& directory) {
    if (!fs::is_directory(directory)) throw Error("--collect: '" + directory + "' is not a folder");
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.is_directory() && entry.path().filename().string().rfind("run_", 0) == 0)
            folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    std::string csv =
        "run,status,exit_status,speed_mps,dir_x,dir_y,dir_z,point_x,point_y,point_z,normal_x,normal_y,normal_"
        "z,"
        "impactor_scale,impactor_mass_kg,orient_w,orient_x,orient_y,orient_z,seed,method,steps,fracture_"
        "events,"
        "fragments,first_contact_s,total_impulse_Ns,wall_s,fracture_s,cpu_s,peak_memory_mb,host,error\n";
    int rows = 0, unfinished = 0;
    for (const fs::path& dir : folders) {
        std::ifstream in(dir / "run.json");
        if (!in) {
            ++unfinished;
            continue;
        }
        const Json run = Json::parse(in);
        Json timing = Json::object();
        if (std::ifstream t(dir / "timing.json"); t) timing = Json::parse(t);
        const Json& p = run["parameters"];
        const Json& impact = run["impact"];
        std::vector<std::string> f = {csvNumber(run["run"]), csvNumber(run["status"]),
                                      csvNumber(run["exit_status"]), csvNumber(p["speed_mps"])};
        for (const char* key : {"direction", "impact_point_rest", "impact_normal_rest"})
            for (int i = 0; i < 3; ++i) f.push_back(csvNumber(p[key][i]));
        f.push_back(csvNumber(p["impactor_scale"]));
        f.push_back(csvNumber(p["impactor_mass_kg"]));
        for (int i = 0; i < 4; ++i) f.push_back(csvNumber(p["target_orientation_wxyz"][i]));
        f.push_back(csvNumber(p["seed"]));
        f.push_back(csvNumber(p["method"]));
        for (const char* key : {"steps_taken", "fracture_events", "fragments"})
            f.push_back(csvNumber(run[key]));
        f.push_back(csvNumber(impact.value("first_contact_s", Json())));
        f.push_back(csvNumber(impact.value("total_impulse_Ns", Json())));
        const Json seconds = timing.value("seconds", Json::object());
        f.push_back(csvNumber(seconds.value("total", Json())));
        f.push_back(csvNumber(seconds.value("fracture", Json())));
        f.push_back(csvNumber(timing.value("cpu_seconds", Json())));
        f.push_back(csvNumber(timing.value("peak_memory_mb", Json())));
        f.push_back(csvNumber(timing.value("host", Json(""))));
        f.push_back(csvNumber(run["error"]));
        for (size_t i = 0; i < f.size(); ++i) csv += (i ? "," : "") + f[i];
        csv += "\n";
        ++rows;
    }
    writeFileAtomically((fs::path(directory) / "index.csv").string(), csv);
    std::printf("btfracture-sweep: %s/index.csv: %d finished runs (%d unfinished folders left out)\n",
                directory.c_str(), rows, unfinished);
    return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parseOptions(argc, argv);
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-sweep: error: %s\n%s(try --help)\n", e.what(), kUsage);
        return kBadInput;
    }
    try {
        if (!options.collect.empty()) return collect(options.collect);
        SweepSpec spec;
        std::optional<SweepRunBuilder> builder;
        try {
            spec = readSweepFile(options.sweep);
            if (options.runOne) {
                setLogLevel(LogLevel::Warning);
                if (*options.runOne >= spec.runs)
                    throw Error("--run-one: no run " + std::to_string(*options.runOne));
                return runOne(options, spec, *options.runOne);
            }
            builder.emplace(spec);  // checks the scene, the target and the impactor
            if (options.list) {
                for (int index : shareOf(options, spec)) std::printf("%d\n", index);
                return kSuccess;
            }
        } catch (const Error& e) {
            std::fprintf(stderr, "btfracture-sweep: error: %s\n", e.what());
            return kBadInput;
        }
        return runShare(options, spec, *builder, argv[0]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "btfracture-sweep: internal failure: %s\n", e.what());
        return kInternalFailure;
    }
}
