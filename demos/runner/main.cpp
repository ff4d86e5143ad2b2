// SPDX-License-Identifier: Zlib
// btfracture-run: the headless runner. Reads a JSON scene (demos/README.md) or a FractureRB
// .bullet + CSV pair, simulates it and writes the outputs the scene asks for (OBJ and PNG frames,
// a contact sheet, fracture statistics) and run.json, then prints a summary table. --check
// validates the scene and its meshes and writes nothing.
//
// Exit codes (also in --help and demos/README.md):
//   0  the run finished (--check: the scene is valid)
//   1  internal failure while running (unexpected exception, an output file that cannot be written)
//   2  bad input, rejected before simulating (command line, scene, meshes, CSV, output folder)
//   3  the simulation turned non-finite (NaN or Inf); the run stopped there, outputs so far are kept
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/ThreadLimit.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/io/ContactSheet.h>
#include <btFracture/io/FractureRbScene.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/MotionRecorder.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/PngFile.h>
#include <btFracture/io/RunRecord.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneFractureListener.h>
#include <btFracture/io/ScenePreview.h>
#include <btFracture/io/SceneWorld.h>
#include <btFracture/io/Sha256.h>

#include <btBulletDynamicsCommon.h>

#include "RunnerVersion.h"  // generated: BTFRACTURE_VERSION, BTFRACTURE_SOURCE_REVISION

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace btfracture;
namespace fs = std::filesystem;

enum ExitCode { kSuccess = 0, kInternalFailure = 1, kBadInput = 2, kNonFinite = 3 };

const char* kUsage =
    "usage: btfracture-run SCENE [options]\n"
    "       btfracture-run --fracturerb SCENE.bullet PARAMS.csv [options]\n"
    "       btfracture-run --version\n";

const char* kHelp =
    "Simulates a btFracture scene headless and writes what the scene's effects.outputs ask for.\n"
    "\n"
    "  SCENE          scene file (JSON; format in demos/README.md)\n"
    "  --fracturerb SCENE.bullet PARAMS.csv\n"
    "                 read a FractureRB scene instead: a Bullet world file and the per-object CSV\n"
    "                 of Hahn & Wojtan's FractureRB (';'-separated, '%' comments); time step 1/250 s,\n"
    "                 1000 steps and outputs motion,gltf,csv,png unless overridden\n"
    "  --out DIR      output folder (default: the scene's outputs.directory, else out/<scene name>);\n"
    "                 when the run starts writing, the files of an earlier run in it (motion.csv,\n"
    "                 meshes/*.obj, scene.glb, frame_*.obj, frame_*.png, run.json, ...) are removed\n"
    "  --check        validate the scene and its meshes (everything a run checks before it\n"
    "                 simulates), print what was checked and exit: 0 valid, 2 not; writes and\n"
    "                 deletes nothing\n"
    "  --steps N      simulate N frames instead of the scene's world.steps\n"
    "  --method M     fracture method of every breakable body: full (BEM with crack unknowns, Eq. 4),\n"
    "                 est (SIF estimator, paper section 4.2) or hybrid (full until the body's\n"
    "                 hybrid_threshold BEM elements, then est); default: each body's effects entry\n"
    "  --seed S       run seed (integer >= 0), combined with every body's material-noise seed;\n"
    "                 default: the scene's effects.seed (0). Same seed, same results.\n"
    "  --threads T    worker threads for OpenMP and TBB (0 = all cores, the default); results do\n"
    "                 not depend on it\n"
    "  --outputs L    comma-separated subset of motion,gltf,obj,vdb,csv,png, or none; replaces\n"
    "                 effects.outputs (default motion,gltf)\n"
    "  --quiet        print only warnings and errors: no progress, no summary\n"
    "  --verbose      also print the debug log (every crack step: front nodes, K/K_c, arrests)\n"
    "  --version      print the version and the source revision it was built from\n"
    "  --help         this text\n"
    "\n"
    "Progress goes to stderr: a bar on a terminal, a line every 10 % otherwise. The summary table\n"
    "(steps, fracture events, fragments, rigid-body and fracture time, peak memory, outputs) goes\n"
    "to stdout.\n"
    "\n"
    "Outputs in DIR: meshes/<body>.obj (each body's mesh once, in its body frame, crack faces under\n"
    "usemtl interior) and motion.csv (pose, velocities and alive flag of every body, every\n"
    "outputs.motion_every_n_steps), scene.glb (the same as a glTF 2.0 animation),\n"
    "frame_NNNNN.obj (one object per body in world coordinates, every outputs.obj_every_n_steps),\n"
    "frame_NNNNN.png and contact_sheet.png (every outputs.png_every_n_steps), statistics.csv (one\n"
    "row per fracture event), fragments.csv and fragment_volumes.csv/.png (fragment volumes\n"
    "against Mott's distribution; written when something broke), levelset_<body>_NNN.vdb (the body's\n"
    "OpenVDB level set right after each fracture event's cuts: grids <body>.object and <body>.cracks),\n"
    "run.json (what made the folder: version, source revision, command line, input files and their\n"
    "SHA-256, seed, threads, overrides, start and end time, exit status, time per phase, event and\n"
    "fragment counts, peak memory; written last).\n"
    "\n"
    "Exit status: 0 success, 1 internal failure while running, 2 bad input (command line, scene,\n"
    "mesh, CSV or output folder; nothing was simulated), 3 the simulation turned non-finite (NaN or\n"
    "Inf) and stopped (outputs up to that step are kept). --check exits 0 for a valid scene, 2 else.\n";

struct Options {
    std::string scene;
    std::optional<std::pair<std::string, std::string>> fractureRb;  // .bullet, .csv
    std::optional<std::string> out;
    std::optional<int> steps;
    std::optional<FractureMethod> method;
    std::optional<std::uint64_t> seed;
    std::optional<int> threads;
    std::optional<SceneOutputFormats> outputs;
    bool quiet = false;
    bool verbose = false;  // debug log
    bool check = false;    // validate only
    std::vector<std::string> commandLine;
    std::vector<std::pair<std::string, std::string>> overrides;  // options that replace scene values
};

std::string versionText() {
    return std::string("btfracture-run ") + BTFRACTURE_VERSION + " (source " + BTFRACTURE_SOURCE_REVISION +
           ", Bullet " + (sizeof(btScalar) == 8 ? "double" : "float") + ")";
}

long long integerOption(const std::string& option, const std::string& text, long long minimum,
                        long long maximum, const std::string& expected) {
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < minimum || value > maximum)
        throw Error(option + " expects " + expected + ", got '" + text + "'");
    return value;
}

SceneOutputFormats outputList(const std::string& text) {
    const std::string expected =
        "--outputs: expected a comma-separated subset of motion,gltf,obj,vdb,csv,png or none, got '";
    SceneOutputFormats f;
    f.motion = f.gltf = false;
    if (text == "none") return f;
    std::istringstream items(text);
    std::string item;
    int count = 0;
    while (std::getline(items, item, ',')) {
        bool* flag = item == "motion" ? &f.motion
                     : item == "gltf" ? &f.gltf
                     : item == "obj"  ? &f.obj
                     : item == "vdb"  ? &f.vdb
                     : item == "csv"  ? &f.csv
                     : item == "png"  ? &f.png
                                      : nullptr;
        if (!flag) throw Error(expected + text + "'");
        *flag = true;
        ++count;
    }
    if (count == 0) throw Error(expected + "'");
    return f;
}

// Bad command lines are input errors (exit 2).
Options parseOptions(int argc, char** argv) {
    Options options;
    options.commandLine.assign(argv, argv + argc);
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&](const char* option) {
            if (i + 1 >= argc) throw Error(std::string(option) + " needs a value");
            if (arg != "--fracturerb") options.overrides.emplace_back(option, argv[i + 1]);
            return std::string(argv[++i]);
        };
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            std::fputs(kHelp, stdout);
            std::exit(kSuccess);
        } else if (arg == "--version") {
            std::printf("%s\n", versionText().c_str());
            std::exit(kSuccess);
        } else if (arg == "--check") {
            options.check = true;
        } else if (arg == "--out") {
            options.out = value("--out");
            if (options.out->empty()) throw Error("--out needs a non-empty folder");
        } else if (arg == "--steps") {
            options.steps = static_cast<int>(
                integerOption("--steps", value("--steps"), 0, 1000000000, "an integer >= 0"));
        } else if (arg == "--method") {
            options.method = parseFractureMethod(value("--method"), "--method");
        } else if (arg == "--seed") {
            const std::string text = value("--seed");
            char* end = nullptr;
            errno = 0;
            const unsigned long long seed = std::strtoull(text.c_str(), &end, 10);
            if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0)
                throw Error("--seed expects an integer >= 0, got '" + text + "'");
            options.seed = seed;
        } else if (arg == "--threads") {
            options.threads = static_cast<int>(integerOption("--threads", value("--threads"), 0, 1024,
                                                             "an integer in [0, 1024] (0 = all cores)"));
        } else if (arg == "--outputs") {
            options.outputs = outputList(value("--outputs"));
        } else if (arg == "--fracturerb") {
            const std::string bullet = value("--fracturerb");
            options.fractureRb = std::make_pair(bullet, value("--fracturerb"));
        } else if (arg == "--quiet" || arg == "-q") {
            options.quiet = true;
        } else if (arg == "--verbose" || arg == "-v") {
            options.verbose = true;
        } else if (!arg.empty() && arg[0] == '-') {
            throw Error("unknown option '" + arg + "'");
        } else if (options.scene.empty()) {
            options.scene = arg;
        } else {
            throw Error("more than one scene given ('" + options.scene + "', '" + arg + "')");
        }
    }
    if (options.quiet && options.verbose) throw Error("--quiet and --verbose contradict each other");
    if (options.fractureRb && !options.scene.empty())
        throw Error("give either a SCENE or --fracturerb SCENE.bullet PARAMS.csv, not both");
    if (!options.fractureRb && options.scene.empty()) throw Error("no scene file given");
    return options;
}

// Files a run writes; removed from the output folder first so that no stale frame survives.
bool isRunOutput(const fs::path& file) {
    const std::string name = file.filename().string(), ext = file.extension().string();
    if (name.rfind("frame_", 0) == 0 && (ext == ".obj" || ext == ".png")) return true;
    if (name.rfind("levelset_", 0) == 0 && ext == ".vdb") return true;
    for (const char* own : {"motion.csv", "scene.glb", "contact_sheet.png", "statistics.csv", "fragments.csv",
                            "fragment_volumes.csv", "fragment_volumes.png", "run.json", "run.json.tmp"})
        if (name == own) return true;
    return false;
}

fs::path prepareOutput(const std::string& directory) {
    const fs::path dir(directory);
    std::error_code error;
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir))
        throw Error("cannot create output folder '" + directory + "'" +
                    (error ? ": " + error.message() : ""));
    int removed = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && isRunOutput(entry.path())) {
            fs::remove(entry.path());
            ++removed;
        }
    // meshes/: the body meshes and their material library
    if (fs::is_directory(dir / "meshes"))
        for (const auto& entry : fs::directory_iterator(dir / "meshes"))
            if (entry.is_regular_file() &&
                (entry.path().extension() == ".obj" || entry.path().filename() == "materials.mtl")) {
                fs::remove(entry.path());
                ++removed;
            }
    if (removed > 0) logf(LogLevel::Info, "removed ", removed, " files of an earlier run from ", directory);
    return dir;
}

// Output at step 0, every `every` steps and at the last step (every = 0: never).
bool isOutputStep(int step, int every, int steps) {
    return every > 0 && (step % every == 0 || step == steps);
}
int outputCount(int every, int steps) {
    int count = 0;
    for (int step = 0; step <= steps; ++step) count += isOutputStep(step, every, steps) ? 1 : 0;
    return count;
}

std::string frameName(int index, const char* extension) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.%s", index, extension);
    return name;
}

// Runs scripts/charts/<script> with the chart Python (cmake/ChartPython.cmake) on `arguments`;
// false, with a note in the log, when there is no such Python or the script failed.
bool drawChart(const char* script, const std::vector<std::string>& arguments) {
    const std::string python = BTFRACTURE_CHART_PYTHON;
    const std::string path = std::string(BTFRACTURE_CHART_SCRIPTS) + "/" + script;
    if (python.empty() || !fs::exists(path)) {
        logf(LogLevel::Info, "btfracture-run: no ", script,
             " chart: it needs Python 3 with matplotlib (python3-matplotlib) and ", path);
        return false;
    }
    std::vector<std::string> words{python, path};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    pid_t child = 0;
    int status = 0;
    if (posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0 ||
        waitpid(child, &status, 0) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        logf(LogLevel::Warning, "btfracture-run: ", path, " failed; no chart");
        return false;
    }
    return true;
}

double peakMemoryMegabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

std::string clock(double seconds) {
    const long s = std::lround(seconds);
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

// Progress on stderr: an updating bar on a terminal, a plain line every 10 % otherwise.
class Progress {
public:
    Progress(int total, bool enabled)
        : total_(total), enabled_(enabled && total > 0), tty_(isatty(fileno(stderr))) {}

    void update(int step, double simulatedTime) {
        if (!enabled_) return;
        const int percent = static_cast<int>(100LL * step / total_);
        if (tty_) {
            if (step != total_ && sinceDraw_.seconds() < 0.1) return;
            sinceDraw_.restart();
            const int width = 30, filled = width * step / total_;
            const double elapsed = wall_.seconds();
            const double eta = step > 0 ? elapsed * (total_ - step) / step : 0.0;
            std::fprintf(stderr, "\r[%s%s] %3d%%  step %d/%d  t = %.3f s  %s elapsed, %s left ",
                         std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), percent,
                         step, total_, simulatedTime, clock(elapsed).c_str(), clock(eta).c_str());
            if (step == total_) std::fputc('\n', stderr);
            std::fflush(stderr);
        } else if (percent / 10 > lastTenth_ || step == total_) {
            lastTenth_ = percent / 10;
            std::fprintf(stderr, "btfracture-run: step %d/%d (%d%%), t = %.3f s, %.1f s elapsed\n", step,
                         total_, percent, simulatedTime, wall_.seconds());
        }
    }
    // Ends an unfinished bar's line (a run stopped early).
    void interrupt() {
        if (enabled_ && tty_) std::fputc('\n', stderr);
    }

private:
    int total_;
    bool enabled_, tty_;
    int lastTenth_ = 0;
    Timer wall_, sinceDraw_;
};

struct Summary {
    std::vector<std::pair<std::string, std::string>> rows;
    void add(const std::string& quantity, const std::string& value) { rows.emplace_back(quantity, value); }
    void print(const std::string& title) const {
        size_t width = 8;
        for (const auto& row : rows) width = std::max(width, row.first.size());
        std::printf("btfracture-run: %s\n", title.c_str());
        for (const auto& [quantity, value] : rows)
            std::printf("  %-*s  %s\n", static_cast<int>(width), quantity.c_str(), value.c_str());
    }
};

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

bool anyBreakable(const Scene& scene) {
    for (const SceneBody& body : scene.bodies)
        if (body.fracture.fracturable) return true;
    return false;
}

// Setup: everything that can reject the input. Errors here exit with 2.
struct Setup {
    Scene scene;
    std::string title;
    fs::path directory;
};

Setup setUp(const Options& options) {
    Setup s;
    if (options.fractureRb) {
        s.scene = readFractureRbScene(options.fractureRb->first, options.fractureRb->second);
        s.title = options.fractureRb->first + " + " + options.fractureRb->second;
    } else {
        s.scene = readSceneFile(options.scene);
        s.title = options.scene;
    }
    Scene& scene = s.scene;
    if (options.steps) scene.world.steps = *options.steps;
    if (options.method) overrideFractureMethod(scene, *options.method);
    if (options.seed) scene.effects.seed = *options.seed;
    if (options.threads) scene.run.threads = *options.threads;
    if (options.outputs) scene.effects.outputs = *options.outputs;
    s.directory = options.out                        ? *options.out
                  : !scene.outputs.directory.empty() ? scene.outputs.directory
                                                     : "out/" + scene.name;
    return s;
}

// The files a run reads, with their SHA-256: the scene (or the FractureRB pair) and every mesh
// file the scene names.
std::vector<RunInput> inputFiles(const Options& options, const Scene& scene) {
    std::vector<RunInput> inputs;
    const auto add = [&](const char* role, const std::string& path) {
        inputs.push_back({role, path, sha256OfFile(path)});
    };
    if (options.fractureRb) {
        add("scene", options.fractureRb->first);
        add("fracturerb_csv", options.fractureRb->second);
    } else {
        add("scene", options.scene);
    }
    std::set<std::string> meshes;
    for (const SceneBody& body : scene.bodies)
        if (!body.shape.meshFile.empty() && meshes.insert(body.shape.meshFile).second)
            add("mesh", body.shape.meshFile);
    return inputs;
}

// One run of a checked scene in `dir`: steps it, writes the outputs and the summary, and fills
// `record` as it goes (so that a run that throws still says how far it got).
int simulate(const Options& options, const Setup& setup, SceneWorld& world, const fs::path& dir,
             std::optional<FractureRecorderListener>& recorderListener, const int& levelSetFiles,
             const Timer& total, RunRecord& record) {
    const Scene& scene = setup.scene;
    const SceneOutputFormats& formats = scene.effects.outputs;
    const ThreadLimit threads(scene.run.threads);
    record.openmpThreads = ThreadLimit::openmpThreads();
    record.tbbThreads = ThreadLimit::tbbThreads();

    FractureRecorder recorder(formats.csv ? (dir / "statistics.csv").string() : std::string());
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    std::optional<SceneFractureListener> sceneListener;
    int breakable = 0;
    if (fractureWorld) {
        recorderListener.emplace(recorder, scene.world.dt / scene.world.substeps);
        for (const auto& body : world.bodies())
            if (btFractureRigidBody::upcast(body.rigidBody)) ++breakable;
        sceneListener.emplace(*recorderListener, world);
        fractureWorld->addFractureListener(&*sceneListener);
    }
    record.breakableBodies = breakable;
    if (formats.vdb && breakable == 0)
        logf(LogLevel::Warning, "btfracture-run: vdb output needs breakable bodies; none in this scene");

    const int steps = scene.world.steps;
    const int motionEvery = formats.motion || formats.gltf ? scene.outputs.motionEveryNSteps : 0;
    std::optional<MotionRecorder> motion;
    if (motionEvery > 0)
        motion.emplace(dir.string(), formats.motion, formats.gltf ? (dir / "scene.glb").string() : "");
    const int objEvery = formats.obj ? scene.outputs.objEveryNSteps : 0;
    const int pngEvery = formats.png ? scene.outputs.pngEveryNSteps : 0;
    std::optional<ScenePreview> preview;
    if (pngEvery > 0) preview.emplace(world, scene.outputs.image);
    // Contact sheet: at most 16 evenly spaced PNG frames, kept as thumbnails.
    const int thumbnailWidth = std::max(16, scene.outputs.image.width / 4);
    const int thumbnailHeight =
        std::max(1, static_cast<int>(std::lround(static_cast<double>(scene.outputs.image.height) *
                                                 thumbnailWidth / scene.outputs.image.width)));
    const std::vector<size_t> sheetFrames =
        contactSheetSelection(static_cast<size_t>(outputCount(pngEvery, steps)), 16);
    std::vector<Image> thumbnails;
    std::vector<std::string> thumbnailLabels;

    const double setupSeconds = total.seconds();
    double stepSeconds = 0.0, motionSeconds = 0.0, objSeconds = 0.0, renderSeconds = 0.0, pngSeconds = 0.0;
    int objFrames = 0, pngFrames = 0, stepsTaken = 0;
    // The record's counters and times, as they stand (after every step, and at the end).
    const auto tally = [&] {
        const double fractureSeconds =
            fractureWorld ? fractureWorld->fractureStatistics().fractureSeconds() : 0.0;
        record.stepsTaken = stepsTaken;
        record.bodies = static_cast<int>(world.bodies().size());
        record.fractureEvents = recorder.events();
        record.maxLoadRatio = fractureWorld ? fractureWorld->fractureStatistics().maxLoadRatio : 0.0;
        record.seconds = {setupSeconds, stepSeconds - fractureSeconds, fractureSeconds,
                          motionSeconds + objSeconds + renderSeconds + pngSeconds, total.seconds()};
    };
    auto output = [&](int step) {
        if (isOutputStep(step, motionEvery, steps)) {
            Timer timer;
            motion->sample(world);
            motionSeconds += timer.seconds();
        }
        if (isOutputStep(step, objEvery, steps)) {
            Timer timer;
            ObjWriter writer((dir / frameName(objFrames++, "obj")).string());
            for (size_t i = 0; i < world.bodies().size(); ++i)
                writer.addObject(world.bodies()[i].name, world.worldSurface(i));
            writer.close();
            objSeconds += timer.seconds();
        }
        if (isOutputStep(step, pngEvery, steps)) {
            Timer timer;
            char label[64];
            std::snprintf(label, sizeof label, "step %d  t = %.3f s", step, world.time());
            Image frame = preview->render(world);
            renderSeconds += timer.seconds();
            timer.restart();
            if (std::find(sheetFrames.begin(), sheetFrames.end(), static_cast<size_t>(pngFrames)) !=
                sheetFrames.end()) {
                thumbnails.push_back(frame.resized(thumbnailWidth, thumbnailHeight));
                thumbnailLabels.push_back(format("t = %.3f s", world.time()));
            }
            preview->label(frame, label);
            writePng((dir / frameName(pngFrames, "png")).string(), frame);
            ++pngFrames;
            pngSeconds += timer.seconds();
        }
    };

    Progress progress(steps, !options.quiet);
    std::string nonFinite;
    output(0);
    for (int step = 1; step <= steps; ++step) {
        Timer timer;
        world.stepFrame();
        stepSeconds += timer.seconds();
        stepsTaken = step;
        if (const SceneWorld::Body* body = world.firstNonFiniteBody())
            nonFinite = "body '" + body->name + "' became non-finite (NaN or Inf) at step " +
                        std::to_string(step) + " (t = " + format("%.6g", world.time()) + " s)";
        tally();
        if (!nonFinite.empty()) break;
        output(step);
        progress.update(step, world.time());
    }
    if (!nonFinite.empty()) progress.interrupt();

    Timer finishing;
    if (!thumbnails.empty())
        writePng((dir / "contact_sheet.png").string(),
                 contactSheet(thumbnails, thumbnailLabels, 4, thumbnailWidth));
    if (fractureWorld) fractureWorld->finishEnergyAudits();
    recorder.close();
    if (motion) {
        Timer timer;
        motion->close();
        motionSeconds += timer.seconds();
    }
    const bool histogram =
        formats.csv && recorder.writeFragmentVolumes((dir / "fragment_volumes.csv").string(),
                                                     (dir / "fragments.csv").string());
    const bool chart = histogram && formats.png &&
                       drawChart("fragment_volumes.py",
                                 {(dir / "fragments.csv").string(), (dir / "fragment_volumes.csv").string(),
                                  (dir / "fragment_volumes.png").string()});
    pngSeconds += finishing.seconds();
    record.fragments = static_cast<int>(recorder.fragments().size());
    tally();

    std::vector<std::string>& written = record.outputs;
    if (motion && formats.motion)
        written.push_back(std::to_string(motion->bodies()) + " body meshes meshes/<body>.obj, motion.csv (" +
                          std::to_string(motion->samples()) + " samples, every " +
                          std::to_string(motionEvery) + " steps)");
    if (motion && formats.gltf) written.push_back("scene.glb");
    if (objFrames > 0)
        written.push_back(
            std::to_string(objFrames) + (objFrames == 1 ? " OBJ frame (every " : " OBJ frames (every ") +
            std::to_string(objEvery) + " steps) frame_00000.obj .. " + frameName(objFrames - 1, "obj"));
    if (pngFrames > 0)
        written.push_back(
            std::to_string(pngFrames) + (pngFrames == 1 ? " PNG frame (every " : " PNG frames (every ") +
            std::to_string(pngEvery) + " steps) frame_00000.png .. " + frameName(pngFrames - 1, "png"));
    if (!thumbnails.empty()) written.push_back("contact_sheet.png");
    if (formats.csv) written.push_back("statistics.csv");
    if (histogram) written.insert(written.end(), {"fragments.csv", "fragment_volumes.csv"});
    if (chart) written.push_back("fragment_volumes.png");
    if (levelSetFiles > 0)
        written.push_back(std::to_string(levelSetFiles) + " fractured level set" +
                          (levelSetFiles == 1 ? "" : "s") + " levelset_<body>_NNN.vdb");

    if (!options.quiet) {
        int dynamic = 0;
        for (const auto& body : world.bodies()) dynamic += body.rigidBody->getInvMass() > 0 ? 1 : 0;
        const RunRecord::Seconds& t = record.seconds;
        Summary summary;
        summary.add("steps", std::to_string(stepsTaken) +
                                 (stepsTaken < steps ? " of " + std::to_string(steps) : "") +
                                 format(" x %.4g s = %.4g s simulated", scene.world.dt, world.time()) + " (" +
                                 std::to_string(scene.world.substeps) + " substep" +
                                 (scene.world.substeps == 1 ? "" : "s") + " each)");
        summary.add("bodies", std::to_string(record.bodies) + " (" + std::to_string(dynamic) + " dynamic, " +
                                  std::to_string(record.bodies - dynamic) + " static or kinematic), " +
                                  std::to_string(breakable) + " breakable");
        summary.add("fracture events", std::to_string(record.fractureEvents));
        summary.add("fragments", std::to_string(record.fragments));
        summary.add("largest K/K_c", format("%.3g (any crack front, before its step)", record.maxLoadRatio));
        summary.add("rigid-body time", format("%.2f s (%.3f ms per step)", t.rigidBody,
                                              stepsTaken > 0 ? 1e3 * t.rigidBody / stepsTaken : 0.0));
        summary.add("fracture time", format("%.2f s", t.fracture));
        summary.add("output time",
                    format("%.2f s (motion %.2f s, OBJ %.2f s", t.output, motionSeconds, objSeconds) +
                        format(", PNG %.2f s", renderSeconds + pngSeconds) +
                        (pngFrames > 0 ? format("; %.1f ms render + %.1f ms encode per frame)",
                                                1e3 * renderSeconds / pngFrames, 1e3 * pngSeconds / pngFrames)
                                       : std::string(")")));
        summary.add("setup time", format("%.2f s", t.setup));
        summary.add("wall time", format("%.2f s", total.seconds()));
        summary.add("peak memory", format("%.1f MB (max resident set size)", peakMemoryMegabytes()));
        summary.add("threads", std::to_string(record.openmpThreads) + " OpenMP, " +
                                   std::to_string(record.tbbThreads) + " TBB");
        std::string files;
        for (const std::string& item : written) files += (files.empty() ? "" : ", ") + item;
        summary.add("output", files.empty() ? "none but run.json in " + dir.string() + "/"
                                            : dir.string() + "/ : " + files + ", run.json");
        summary.print(setup.title);
    }
    if (!nonFinite.empty()) {
        record.stopReason = nonFinite;
        std::fprintf(stderr, "btfracture-run: stopped: %s\n", nonFinite.c_str());
        return kNonFinite;
    }
    return kSuccess;
}

int run(const Options& options) {
    Timer total;
    RunRecord record;
    record.startTime = utcTimestamp(std::chrono::system_clock::now());
    Setup setup;
    std::optional<SceneWorld> world;
    std::optional<FractureRecorderListener> recorderListener;
    fs::path dir;
    int levelSetFiles = 0;
    try {
        setup = setUp(options);
        // Breakable bodies: btFractureDynamicsWorld with the BEM engine; the cut observer saves
        // every fractured level set when the scene asks for VDB output.
        FractureSceneWorldFactory fractureFactory(setup.scene.effects.seed);
        if (setup.scene.effects.outputs.vdb)
            fractureFactory.setCutObserver(
                [&](const btFractureRigidBody& body, const LevelSetBody& levelSet) {
                    std::string name = recorderListener ? recorderListener->nameOf(&body) : std::string();
                    if (name.empty()) name = body.name();
                    char file[64];
                    std::snprintf(file, sizeof file, "_%03d.vdb", ++levelSetFiles);
                    levelSet.writeVdb((dir / ("levelset_" + name + file)).string());
                });
        const SceneWorldFactory plainFactory;
        const SceneWorldFactory& factory =
            anyBreakable(setup.scene) ? static_cast<const SceneWorldFactory&>(fractureFactory) : plainFactory;
        world.emplace(setup.scene, factory);  // loads and checks every mesh
        if (options.check) {
            int breakable = 0, meshes = 0;
            for (const SceneBody& body : setup.scene.bodies) {
                breakable += body.fracture.fracturable ? 1 : 0;
                meshes += body.shape.meshFile.empty() ? 0 : 1;
            }
            std::printf(
                "btfracture-run: %s: valid (%zu bodies, %d breakable, %d mesh files checked); nothing "
                "written\n",
                setup.title.c_str(), setup.scene.bodies.size(), breakable, meshes);
            return kSuccess;
        }
        record.inputs = inputFiles(options, setup.scene);
        // The run starts writing: its folder is created and an earlier run's files leave it.
        dir = prepareOutput(setup.directory.string());
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-run: error: %s\n", e.what());
        return kBadInput;
    }
    const Scene& scene = setup.scene;
    record.program = "btfracture-run";
    record.version = BTFRACTURE_VERSION;
    record.sourceRevision = BTFRACTURE_SOURCE_REVISION;
    record.commandLine = options.commandLine;
    std::error_code cwdError;
    record.workingDirectory = fs::current_path(cwdError).string();
    record.bulletPrecision = sizeof(btScalar) == 8 ? "double" : "float";
    record.seed = scene.effects.seed;
    record.threadsRequested = scene.run.threads;
    record.overrides = options.overrides;
    record.stepsRequested = scene.world.steps;
    record.dt = scene.world.dt;
    record.substeps = scene.world.substeps;

    int status = kSuccess;
    try {
        status = simulate(options, setup, *world, dir, recorderListener, levelSetFiles, total, record);
    } catch (const std::exception& e) {
        status = kInternalFailure;
        record.stopReason = std::string("internal failure: ") + e.what();
        std::fprintf(stderr, "btfracture-run: internal failure: %s\n", e.what());
    }
    record.exitStatus = status;
    record.endTime = utcTimestamp(std::chrono::system_clock::now());
    record.seconds.total = total.seconds();
    record.peakMemoryMegabytes = peakMemoryMegabytes();
    try {
        writeRunRecord((dir / "run.json").string(), record);
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-run: internal failure: %s\n", e.what());
        return kInternalFailure;
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parseOptions(argc, argv);
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-run: error: %s\n%s(try --help)\n", e.what(), kUsage);
        return kBadInput;
    }
    if (options.quiet) setLogLevel(LogLevel::Warning);
    if (options.verbose) setLogLevel(LogLevel::Debug);
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "btfracture-run: internal failure: %s\n", e.what());
        return kInternalFailure;
    } catch (...) {
        std::fprintf(stderr, "btfracture-run: internal failure (unknown exception)\n");
        return kInternalFailure;
    }
}
