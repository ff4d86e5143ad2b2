// btfracture-run: the headless runner. Reads a JSON scene (demos/README.md), simulates it in
// Bullet and writes OBJ frames (one object per body) plus a short summary.
//
// Exit codes: 0 success, 2 bad input (command line, scene, meshes, output folder), 1 internal
// failure (anything unexpected, including a simulation that turns non-finite).
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/Timer.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <btBulletDynamicsCommon.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

namespace {

using namespace btfracture;

const char* kUsage = "usage: btfracture-run SCENE [--out DIR] [--steps N] [--quiet] [--help]\n";

const char* kHelp =
    "Simulates a btFracture scene file headless and writes one OBJ file per output frame.\n"
    "\n"
    "  SCENE        scene file (JSON; format in demos/README.md)\n"
    "  --out DIR    output folder (default: the scene's outputs.directory, else out/<scene name>);\n"
    "               old frame_*.obj files in it are removed first\n"
    "  --steps N    simulate N frames instead of the scene's world.steps\n"
    "  --quiet      print only warnings and errors, no summary\n"
    "  --help       this text\n"
    "\n"
    "Output: DIR/frame_00000.obj, ... every outputs.obj_every_n_steps frames (and the first and\n"
    "last), one object per body named after it, in world coordinates.\n"
    "Exit status: 0 success, 2 bad input (scene, mesh, options), 1 internal failure.\n";

struct Options {
    std::string scene;
    std::optional<std::string> out;
    std::optional<int> steps;
    bool quiet = false;
};

// Bad command lines are input errors (exit 2).
Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&](const char* option) {
            if (i + 1 >= argc) throw Error(std::string(option) + " needs a value");
            return std::string(argv[++i]);
        };
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            std::fputs(kHelp, stdout);
            std::exit(0);
        } else if (arg == "--out") {
            options.out = value("--out");
            if (options.out->empty()) throw Error("--out needs a non-empty folder");
        } else if (arg == "--steps") {
            const std::string text = value("--steps");
            char* end = nullptr;
            const long steps = std::strtol(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0' || steps < 0 || steps > 1000000000L)
                throw Error("--steps expects an integer >= 0, got '" + text + "'");
            options.steps = static_cast<int>(steps);
        } else if (arg == "--quiet" || arg == "-q") {
            options.quiet = true;
        } else if (!arg.empty() && arg[0] == '-') {
            throw Error("unknown option '" + arg + "'");
        } else if (options.scene.empty()) {
            options.scene = arg;
        } else {
            throw Error("more than one scene given ('" + options.scene + "', '" + arg + "')");
        }
    }
    if (options.scene.empty()) throw Error("no scene file given");
    return options;
}

std::filesystem::path prepareOutput(const std::string& directory) {
    namespace fs = std::filesystem;
    const fs::path dir(directory);
    std::error_code error;
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir))
        throw Error("cannot create output folder '" + directory + "': " + error.message());
    int removed = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name.rfind("frame_", 0) == 0 && entry.path().extension() == ".obj") {
            fs::remove(entry.path());
            ++removed;
        }
    }
    if (removed > 0) logf(LogLevel::Info, "removed ", removed, " old frame files from ", directory);
    return dir;
}

void writeFrame(const SceneWorld& world, const std::filesystem::path& file) {
    ObjWriter writer(file.string());
    for (size_t i = 0; i < world.bodies().size(); ++i)
        writer.addObject(world.bodies()[i].name, world.worldSurface(i));
    writer.close();
}

bool finite(const btRigidBody& body) {
    const btTransform& t = body.getWorldTransform();
    const btVector3 v = body.getLinearVelocity();
    return std::isfinite(t.getOrigin().x() + t.getOrigin().y() + t.getOrigin().z() + v.x() + v.y() + v.z()) &&
           std::isfinite(t.getRotation().w());
}

int run(const Options& options) {
    Timer total;
    Scene scene = readSceneFile(options.scene);
    if (options.steps) scene.world.steps = *options.steps;
    const std::string directory = options.out                        ? *options.out
                                  : !scene.outputs.directory.empty() ? scene.outputs.directory
                                                                     : "out/" + scene.name;
    const int every = scene.outputs.objEveryNSteps;
    SceneWorld world(scene);  // loads and checks every mesh before anything is written
    const std::filesystem::path dir = prepareOutput(directory);
    const double setupSeconds = total.seconds();
    double simulationSeconds = 0.0, outputSeconds = 0.0;
    int frames = 0;
    auto output = [&] {
        Timer timer;
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.obj", frames++);
        writeFrame(world, dir / name);
        outputSeconds += timer.seconds();
    };
    if (every > 0) output();
    for (int step = 1; step <= scene.world.steps; ++step) {
        Timer timer;
        world.stepFrame();
        simulationSeconds += timer.seconds();
        for (const auto& body : world.bodies())
            if (!finite(*body.rigidBody))
                throw std::runtime_error("body '" + body.name + "' became non-finite at step " +
                                         std::to_string(step));
        if (every > 0 && (step % every == 0 || step == scene.world.steps)) output();
    }

    if (!options.quiet) {
        int dynamic = 0;
        for (const auto& body : world.bodies()) dynamic += body.rigidBody->getInvMass() > 0 ? 1 : 0;
        const int bodies = static_cast<int>(world.bodies().size());
        std::printf("btfracture-run: %s\n", options.scene.c_str());
        std::printf("  steps      %d x %.4g s = %.4g s simulated (%d substep%s each)\n", scene.world.steps,
                    scene.world.dt, world.time(), scene.world.substeps, scene.world.substeps == 1 ? "" : "s");
        std::printf("  bodies     %d (%d dynamic, %d static)\n", bodies, dynamic, bodies - dynamic);
        std::printf("  wall time  %.2f s (setup %.2f s, simulation %.2f s, output %.2f s)\n", total.seconds(),
                    setupSeconds, simulationSeconds, outputSeconds);
        if (frames > 0)
            std::printf(
                "  output     %d OBJ frames (every %d steps) in %s/ : frame_00000.obj .. frame_%05d.obj\n",
                frames, every, dir.string().c_str(), frames - 1);
        else
            std::printf("  output     none (outputs.obj_every_n_steps is 0)\n");
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parseOptions(argc, argv);
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-run: error: %s\n%s(try --help)\n", e.what(), kUsage);
        return 2;
    }
    if (options.quiet) setLogLevel(LogLevel::Warning);
    try {
        return run(options);
    } catch (const Error& e) {
        std::fprintf(stderr, "btfracture-run: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "btfracture-run: internal failure: %s\n", e.what());
        return 1;
    } catch (...) {
        std::fprintf(stderr, "btfracture-run: internal failure (unknown exception)\n");
        return 1;
    }
}
