// SPDX-License-Identifier: Zlib
// Cost of a crack propagation step per method (paper §4.4): FULL (Eq. 4 every step), EST (local
// stress + §4.3 update), HYBRID at two thresholds, on a penny crack growing in a cube of about
// 2,000 surface triangles. Prints per step: crack triangles, active front nodes, step time and
// time per front node, mean K_I and its difference to FULL; then the METRIC lines. Then the
// paper's sizes (Table 1: thousands of crack triangles): EST grows a penny with a crack element
// size of a third of the BEM edge past 5,000 triangles, and FULL takes single steps on EST's
// crack at about 500 and 5,000 triangles. `--large-only` runs just that part.
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/core/Timer.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/FractureSolver.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

struct Sample {
    int crackTriangles, frontNodes;
    double seconds, meanKI;
};

std::vector<Sample> run(const ElasticSolver& solver, const Eigen::VectorXd& q, const Material& material,
                        FractureMethod method, int threshold, int steps) {
    FractureSettings fs;
    fs.method = method;
    fs.hybridElementThreshold = threshold;
    fs.minimumSpeed = 1.0;
    fs.maxNewCracksPerEvent = 0;
    fs.frontEdgeLength = 0.4;
    FractureSolver fracture(solver, MaterialField(material), fs);
    addDiscCrack(fracture.cracks(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.02, 2);
    fracture.beginEvent(q);
    std::vector<Sample> out;
    for (int i = 0; i < steps; ++i) {
        Timer timer;
        const auto sifs = fracture.frontSifs();
        const FractureStepRecord r = fracture.step(i);
        const double seconds = timer.seconds();
        double K = 0.0;
        for (const auto& f : sifs) K += f.KI / sifs.size();
        out.push_back({r.crackTriangles, r.frontNodes, seconds, K});
        if (r.advancedNodes == 0) break;
    }
    return out;
}

// The large cube: 20 x 20 cells per face (4,800 surface triangles, edge 1 cm).
constexpr int kLargeCubeCells = 20;

// One timed step of `method` on a copy of `cracks` (the event set up beforehand, untimed).
struct TimedStep {
    int crackTriangles, frontNodes;
    double seconds;
};
TimedStep stepOn(const ElasticSolver& solver, const Eigen::VectorXd& q, const Material& material,
                 const FractureSettings& settings, const CrackMesh& cracks, int steps) {
    FractureSolver fracture(solver, MaterialField(material), settings);
    fracture.cracks() = cracks;
    fracture.beginEvent(q);
    TimedStep out{cracks.triangleCount(), 0, 0.0};
    for (int i = 0; i < steps; ++i) {
        Timer timer;
        const FractureStepRecord r = fracture.step(i);
        out.seconds += timer.seconds() / steps;
        out.frontNodes += r.frontNodes / steps;
    }
    return out;
}

// The penny past 5,000 crack triangles: a cube of `cells` cells per face edge, crack element
// size a third of the cell edge; EST grows the crack, FULL steps once (or `fullSteps` times) on
// EST's crack at the first step from 500 and from 5,000 crack triangles.
void largeCrack(const Material& material, int cells, int fullSteps) {
    const double side = 0.2, edge = side / cells, h = edge / 3.0;
    Timer setup;
    const ElasticSolver solver(
        SurfaceMesh(makeBox({0.5 * side, 0.5 * side, 0.5 * side}, cells, cells, cells)), material);
    const SurfaceMesh& m = solver.mesh();
    Eigen::VectorXd q(3 * m.triangleCount());
    for (int t = 0; t < m.triangleCount(); ++t)
        q.segment<3>(3 * t) = Eigen::Vector3d(1e6 * m.normal(t).x(), 0, 0);
    std::printf(
        "\nlarge crack: cube of %d surface triangles (edge %.4f m), crack element size %.5f m "
        "(edge / 3), BEM set-up %.1f s\n",
        m.triangleCount(), edge, h, setup.seconds());
    FractureSettings fs;
    fs.method = FractureMethod::Estimated;
    fs.minimumSpeed = 1.0;
    fs.maxNewCracksPerEvent = 0;
    fs.frontEdgeLength = 1.0;
    fs.crackElementSize = h;
    FractureSolver est(solver, MaterialField(material), fs);
    addDiscCrack(est.cracks(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 6 * h, 6);
    est.beginEvent(q);
    std::optional<CrackMesh> at500, at5k;
    std::optional<TimedStep> est500, est5k;
    std::printf("%5s %10s %6s %9s %13s\n", "step", "crack_tris", "front", "step_s", "s_per_front");
    for (int i = 0; i < 200 && !est5k; ++i) {
        const int before = est.cracks().triangleCount();
        const CrackMesh snapshot = est.cracks();
        Timer timer;
        const FractureStepRecord r = est.step(i);
        const double seconds = timer.seconds();
        std::printf("%5d %10d %6d %9.4f %13.2e\n", i, before, r.frontNodes, seconds,
                    seconds / std::max(1, r.frontNodes));
        std::fflush(stdout);
        if (!est500 && before >= 500) est500 = TimedStep{before, r.frontNodes, seconds}, at500 = snapshot;
        if (before >= 5000) est5k = TimedStep{before, r.frontNodes, seconds}, at5k = snapshot;
        if (r.advancedNodes == 0) break;
    }
    if (!est500 || !est5k) {
        std::printf("METRIC est_step_speedup_5k nan ratio (EST arrested at %d crack triangles)\n",
                    est.cracks().triangleCount());
        return;
    }
    std::printf(
        "METRIC est_step_growth_per_front_node_5k %.2f ratio (%d -> %d crack triangles, front %d -> %d "
        "nodes, %.4f -> %.4f s)\n",
        (est5k->seconds / est5k->frontNodes) / (est500->seconds / est500->frontNodes), est500->crackTriangles,
        est5k->crackTriangles, est500->frontNodes, est5k->frontNodes, est500->seconds, est5k->seconds);
    std::fflush(stdout);
    FractureSettings full = fs;
    full.method = FractureMethod::Full;
    const TimedStep full500 = stepOn(solver, q, material, full, *at500, fullSteps);
    std::printf("FULL step on EST's crack of %d triangles: %.3f s (EST %.4f s)\n", full500.crackTriangles,
                full500.seconds, est500->seconds);
    std::printf("METRIC est_step_speedup_500 %.1f ratio\n", full500.seconds / est500->seconds);
    std::fflush(stdout);
    Timer fullTimer;
    const TimedStep full5k = stepOn(solver, q, material, full, *at5k, fullSteps);
    std::printf(
        "FULL step on EST's crack of %d triangles: %.1f s (EST %.3f s; set-up and step %.0f s in all)\n",
        full5k.crackTriangles, full5k.seconds, est5k->seconds, fullTimer.seconds());
    std::printf("METRIC full_step_5k_s %.1f s (%d surface + %d crack triangles)\n", full5k.seconds,
                m.triangleCount(), full5k.crackTriangles);
    std::printf("METRIC est_step_speedup_5k %.1f ratio (FULL %.1f s / EST %.3f s per step)\n",
                full5k.seconds / est5k->seconds, full5k.seconds, est5k->seconds);
}

}  // namespace

int main(int argc, char** argv) {
    const bool largeOnly = argc > 1 && std::string(argv[1]) == "--large-only";
    const Material material(3.1e9, 0.327, 1200.0, 1e9, 1e3, 2.0, "pmma-growing");
    if (largeOnly) {
        largeCrack(material, kLargeCubeCells, 1);
        return 0;
    }
    Timer setup;
    const ElasticSolver solver(SurfaceMesh(makeBox({0.2, 0.2, 0.2}, 13, 13, 13)), material);
    const SurfaceMesh& m = solver.mesh();
    Eigen::VectorXd q(3 * m.triangleCount());
    for (int t = 0; t < m.triangleCount(); ++t)
        q.segment<3>(3 * t) = Eigen::Vector3d(1e6 * m.normal(t).x(), 0, 0);
    std::printf("cube: %d surface triangles, BEM set-up %.2f s\n", m.triangleCount(), setup.seconds());

    const int steps = 40;
    struct Method {
        std::string name;
        FractureMethod method;
        int threshold;
    };
    const std::vector<Method> methods = {{"FULL", FractureMethod::Full, 1 << 30},
                                         {"EST", FractureMethod::Estimated, 1 << 30},
                                         {"HYBRID(+100)", FractureMethod::Hybrid, m.triangleCount() + 100},
                                         {"HYBRID(+400)", FractureMethod::Hybrid, m.triangleCount() + 400}};
    std::map<std::string, std::vector<Sample>> results;
    for (const auto& method : methods)
        results[method.name] = run(solver, q, material, method.method, method.threshold, steps);

    const auto& full = results["FULL"];
    for (const auto& method : methods) {
        const auto& r = results[method.name];
        double total = 0.0, err = 0.0;
        std::printf("\n%s\n%5s %10s %6s %9s %13s %12s %10s\n", method.name.c_str(), "step", "crack_tris",
                    "front", "step_s", "s_per_front", "mean_KI", "vs_FULL");
        for (std::size_t i = 0; i < r.size(); ++i) {
            total += r[i].seconds;
            const double rel = i < full.size() ? r[i].meanKI / full[i].meanKI - 1.0 : NAN;
            if (i < full.size()) err = std::max(err, std::abs(rel));
            std::printf("%5zu %10d %6d %9.4f %13.2e %12.4e %+9.1f%%\n", i, r[i].crackTriangles,
                        r[i].frontNodes, r[i].seconds, r[i].seconds / std::max(1, r[i].frontNodes),
                        r[i].meanKI, 100 * rel);
        }
        std::printf("%s: %zu steps, %.2f s in all, max |K_I / FULL - 1| = %.1f %%\n", method.name.c_str(),
                    r.size(), total, 100 * err);
    }

    // EST cost against crack size at constant front length: first step with >= N crack
    // triangles against the first with >= 10 N.
    const auto& est = results["EST"];
    auto firstWith = [](const std::vector<Sample>& r, int triangles) -> const Sample* {
        for (const auto& s : r)
            if (s.crackTriangles >= triangles) return &s;
        return nullptr;
    };
    const Sample* small = firstWith(est, 40);
    const Sample* large = small ? firstWith(est, 10 * small->crackTriangles) : nullptr;
    if (small && large) {
        std::printf("METRIC est_step_growth %.2f ratio (%d -> %d crack triangles, front %d -> %d nodes)\n",
                    large->seconds / small->seconds, small->crackTriangles, large->crackTriangles,
                    small->frontNodes, large->frontNodes);
        std::printf("METRIC est_step_growth_per_front_node %.2f ratio\n",
                    (large->seconds / large->frontNodes) / (small->seconds / small->frontNodes));
    } else
        std::printf("METRIC est_step_growth nan ratio (the crack did not grow tenfold)\n");
    const Sample* full80 = firstWith(full, 80);
    if (full80)
        std::printf("METRIC full_step_2k_80_s %.3f s (%d surface + %d crack triangles)\n", full80->seconds,
                    m.triangleCount(), full80->crackTriangles);
    // Largest crack both methods still grow with a sizeable front (before the fronts reach the
    // cube's faces and arrest).
    std::size_t last = 0;
    for (std::size_t i = 0; i < std::min(full.size(), est.size()); ++i)
        if (full[i].frontNodes >= 24 && est[i].frontNodes >= 24) last = i;
    std::printf("METRIC full_vs_est_speedup %.1f ratio (at %d crack triangles, %d front nodes)\n",
                full[last].seconds / est[last].seconds, full[last].crackTriangles, full[last].frontNodes);
    std::fflush(stdout);
    largeCrack(material, kLargeCubeCells, 1);
    return 0;
}
