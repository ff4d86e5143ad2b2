// SPDX-License-Identifier: Zlib
// Cost of a crack propagation step per method (paper §4.4): FULL (Eq. 4 every step), EST (local
// stress + §4.3 update), HYBRID at two thresholds, on a penny crack growing in a cube of about
// 2,000 surface triangles. Prints per step: crack triangles, active front nodes, step time and
// time per front node, mean K_I and its difference to FULL; then the METRIC lines.
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/core/Timer.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/FractureSolver.h>

#include <cmath>
#include <cstdio>
#include <map>
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

}  // namespace

int main() {
    const Material material(3.1e9, 0.327, 1200.0, 1e9, 1e3, 2.0, "pmma-growing");
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
    return 0;
}
