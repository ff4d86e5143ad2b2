// SPDX-License-Identifier: Zlib
// The paper's scenes next to its Table 1 (Hahn & Wojtan 2016): each shipped scene that stands
// for one of the paper's is run as the runner would run it with CSV output only, at a BEM
// resolution that gives crack systems of the paper's order (m_max in thousands where the
// paper's is), and reported in the paper's columns: method, fragments f, fracture time t_f,
// fracture events r, m_max and m_all (BEM target + crack triangles of one fracture simulation,
// the largest and the sum over events), rigid-body time t_rb, steps and the rigid-body rate 1/dt.
// The paper's timings are from a 4 x 3.2 GHz machine, ours from this one.
//
//   paper_table [--out DIR] [--scenes DIR] [--only NAME[,NAME...]]
//
// Writes DIR/paper_table.md, DIR/paper_table.csv and DIR/paper/<scene>/statistics.csv (the
// runner's per-event CSV), and prints METRIC lines (fragments and fracture time per scene).
#include <btFracture/core/Error.h>
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
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace btfracture;
namespace fs = std::filesystem;

namespace {

// One row of the paper's Table 1.
struct PaperRow {
    const char* method;
    int fragments;
    double fractureSeconds;
    int events;
    int mMax, mAll;
    double rigidSeconds;  // negative: not given
    int steps;
    int rate;  // 1/dt [1/s]
};

struct Case {
    const char* paperScene;                   // as the paper names it
    const char* scene;                        // demos/scenes/<scene>.json
    std::map<std::string, int> bemTriangles;  // per breakable body; others keep the scene's
    PaperRow paper;
    const char* setup;  // how our scene differs from the paper's
};

const std::vector<Case>& cases() {
    static const std::vector<Case> list = {
        {"Column (Fig. 1)",
         "column_bunny",
         {{"column", 2500}},
         {"EST", 367, 966.81, 18, 7980, 31529, 2628.18, 1000, 250},
         "2 m column with the bunny on top, steel ball thrown at it; column HYBRID (2,000), bunny EST"},
        {"Bunny two-way (Fig. 8)",
         "bunny_smash",
         {{"bunny", 2500}},
         {"EST", 1099, 1328.17, 5, 15381, 35555, 565.92, 500, 250},
         "steel ball dropped on the bunny, weak PMMA-like material, no refracture"},
        {"Brick breaking",
         "brick",
         {{"brick", 1000}},
         {"HYB (300)", 60, 216.11, 26, 412, 7525, 78.18, 500, 2000},
         "one brick hit once by a steel ball (the paper's row: 26 fracturing collisions of at most 412 "
         "triangles)"},
        {"Falling boxes",
         "falling_boxes",
         {},
         {"EST", 654, 706.43, 77, 704, 26879, 1498.49, 1000, 500},
         "boxes falling onto each other"},
        {"Window (Fig. 9)",
         "window",
         {{"pane", 3000}},
         {"EST", 455, 1256.85, 7, 6459, 31186, 1731.38, 1000, 250},
         "6 mm pane held in a fixed frame, steel ball at 20 m/s"},
        {"Window (Fig. 9), free pane",
         "window_pane",
         {},
         {"EST", 455, 1256.85, 7, 6459, 31186, 1731.38, 1000, 250},
         "2 cm pane standing free on the floor, steel ball at 25 m/s"},
        {"Bowl",
         "bowl_drop",
         {{"bowl", 1500}},
         {"EST", 139, 845.99, 14, 3250, 19504, 351.32, 500, 250},
         "bowl dropped onto the ground"},
        {"Armadillos (Fig. 9)",
         "armadillos",
         {},
         {"EST", 148, 885.95, 14, 1792, 18079, 1710.42, 600, 250},
         "two armadillos thrown at each other"},
    };
    return list;
}

// BEM target + crack triangles of every event.
struct SizeProbe : FractureListener {
    std::vector<int> sizes;
    void onFractureEvent(btFractureRigidBody& parent, const std::vector<btFractureRigidBody*>&,
                         const FractureEventInfo& info) override {
        sizes.push_back(parent.settings().bemTriangleTarget + info.crackTriangles);
    }
};

struct Result {
    std::string method;
    int fragments = 0, events = 0, mMax = 0, mAll = 0, steps = 0, rate = 0;
    double fractureSeconds = 0.0, rigidSeconds = 0.0, wallSeconds = 0.0;
};

std::string methods(const Scene& scene) {
    std::string out;
    for (const SceneBody& b : scene.bodies) {
        if (!b.fracture.fracturable) continue;
        std::string m = toString(b.fracture.method);
        std::transform(m.begin(), m.end(), m.begin(), ::toupper);
        if (b.fracture.method == FractureMethod::Hybrid)
            m += " (" + std::to_string(b.fracture.hybridElementThreshold) + ")";
        if (out.find(m) == std::string::npos) out += (out.empty() ? "" : ", ") + m;
    }
    return out;
}

Result run(const Case& c, const fs::path& scenes, const fs::path& out) {
    Scene scene = readSceneFile((scenes / (std::string(c.scene) + ".json")).string());
    for (SceneBody& b : scene.bodies) {
        const auto it = c.bemTriangles.find(b.name);
        if (it == c.bemTriangles.end() || !b.fracture.fracturable) continue;
        b.fracture.bemTriangleTarget = it->second;
        b.fracture.collisionTriangleTarget = std::max(b.fracture.collisionTriangleTarget, 2 * it->second);
    }
    scene.effects.outputs = SceneOutputFormats{};
    scene.effects.outputs.csv = true;
    const fs::path dir = out / "paper" / c.scene;
    fs::create_directories(dir);
    const Timer wall;
    const ThreadLimit threads(scene.run.threads);
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    if (!fractureWorld) throw Error(std::string(c.scene) + ": no breakable body");
    FractureRecorder recorder((dir / "statistics.csv").string());
    const double step = scene.world.dt / scene.world.substeps;
    FractureRecorderListener names(recorder, step);
    SceneFractureListener sceneListener(names, world);
    SizeProbe sizes;
    fractureWorld->addFractureListener(&sizes);  // before the scene listener retires the parent
    fractureWorld->addFractureListener(&sceneListener);
    double stepSeconds = 0.0;
    for (int i = 0; i < scene.world.steps; ++i) {
        const Timer timer;
        world.stepFrame();
        stepSeconds += timer.seconds();
    }
    recorder.close();
    Result r;
    r.method = methods(scene);
    r.fragments = static_cast<int>(recorder.fragments().size());
    r.events = recorder.events();
    r.fractureSeconds = fractureWorld->fractureStatistics().fractureSeconds();
    r.rigidSeconds = stepSeconds - r.fractureSeconds;
    for (const int m : sizes.sizes) {
        r.mMax = std::max(r.mMax, m);
        r.mAll += m;
    }
    r.steps = scene.world.steps * scene.world.substeps;
    r.rate = static_cast<int>(std::lround(1.0 / step));
    r.wallSeconds = wall.seconds();
    return r;
}

std::string number(double value, const char* format) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// 12345 -> "12,345"
std::string grouped(long value) {
    std::string digits = std::to_string(value), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "bench/results";
    fs::path scenes = fs::path(BTFRACTURE_MESH_DIR) / ".." / "scenes";
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (arg == "--scenes" && i + 1 < argc) {
            scenes = argv[++i];
        } else if (arg == "--only" && i + 1 < argc) {
            only = argv[++i];
        } else {
            std::fprintf(stderr, "usage: paper_table [--out DIR] [--scenes DIR] [--only NAME[,NAME...]]\n");
            return 2;
        }
    }
    fs::create_directories(out);
    std::ostringstream md, csv;
    csv << "scene,paper_scene,source,method,fragments,fracture_s,events,m_max,m_all,rigid_s,steps,rate_per_s,"
           "wall_s\n";
    md << "| scene | | method | f | t_f | r | m_max | m_all | t_rb | steps | 1/dt |\n"
          "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const Timer total;
    for (const Case& c : cases()) {
        if (!only.empty() && ("," + only + ",").find("," + std::string(c.scene) + ",") == std::string::npos)
            continue;
        std::fprintf(stderr, "paper_table: %s (%s.json) ...\n", c.paperScene, c.scene);
        Result r;
        try {
            r = run(c, scenes, out);
        } catch (const Error& e) {
            std::fprintf(stderr, "paper_table: %s: %s\n", c.scene, e.what());
            return 1;
        }
        const PaperRow& p = c.paper;
        md << "| " << c.paperScene << " | paper | " << p.method << " | " << grouped(p.fragments) << " | "
           << number(p.fractureSeconds, "%.0f s") << " | " << p.events << " | " << grouped(p.mMax) << " | "
           << grouped(p.mAll) << " | " << number(p.rigidSeconds, "%.0f s") << " | " << p.steps << " | "
           << p.rate << " |\n";
        md << "| `" << c.scene << "`: " << c.setup << " | ours | " << r.method << " | "
           << grouped(r.fragments) << " | " << number(r.fractureSeconds, "%.1f s") << " | " << r.events
           << " | " << grouped(r.mMax) << " | " << grouped(r.mAll) << " | "
           << number(r.rigidSeconds, "%.1f s") << " | " << r.steps << " | " << r.rate << " |\n";
        csv << c.scene << ",\"" << c.paperScene << "\",paper," << p.method << "," << p.fragments << ","
            << p.fractureSeconds << "," << p.events << "," << p.mMax << "," << p.mAll << "," << p.rigidSeconds
            << "," << p.steps << "," << p.rate << ",\n";
        csv << c.scene << ",\"" << c.paperScene << "\",ours,\"" << r.method << "\"," << r.fragments << ","
            << number(r.fractureSeconds, "%.2f") << "," << r.events << "," << r.mMax << "," << r.mAll << ","
            << number(r.rigidSeconds, "%.2f") << "," << r.steps << "," << r.rate << ","
            << number(r.wallSeconds, "%.1f") << "\n";
        std::printf("METRIC paper_%s_fragments %d count\n", c.scene, r.fragments);
        std::printf("METRIC paper_%s_fracture_time %.2f s\n", c.scene, r.fractureSeconds);
        std::printf("METRIC paper_%s_wall_time %.1f s\n", c.scene, r.wallSeconds);
        std::fflush(stdout);
        // Written after every scene, so that a long run keeps what it measured.
        std::ofstream((out / "paper_table.md").string())
            << "# The paper's Table 1 next to btFracture's runs\n\n"
               "Paper: Hahn & Wojtan 2016, Table 1 (4 x 3.2 GHz). Ours: `paper_table` (`make bench-paper`) "
               "on this\n"
               "machine (2 cores), each scene run with CSV output only; m = BEM target + crack triangles of "
               "one\n"
               "fracture simulation. Per-event CSVs: `paper/<scene>/statistics.csv`.\n\n"
            << md.str() << "\nWall time of these runs " << number(total.seconds(), "%.0f s") << ".\n";
        std::ofstream((out / "paper_table.csv").string()) << csv.str();
    }
    return 0;
}
