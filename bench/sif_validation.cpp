// SPDX-License-Identifier: Zlib
// FULL stress intensity factors (Eq. 4 and the displacement correlation) against closed-form and
// handbook solutions, and EST's (§4.2-4.3) against FULL's: each case prints its lines and
// `METRIC <name> <relative error> ratio`; add one to `cases` below. Edge crack and notched beam:
// mesh size, K_I of FULL, EST and the handbook at mid-thickness, FULL's error and EST's
// deviation from FULL. The edge crack grown a few steps by each method: K_I of both at
// mid-thickness per step. Penny crack of radius a in a cube of side 8 a under tension normal to
// it (Kassir & Sih): per ring count, the mean and worst-node K_I error and the largest change of
// a node's K_I when the disc pattern is turned by 30 degrees (same polar angle). Then both with
// crack elements finer than the BEM surface's (h = BEM edge, / 2, / 3). Semicircular surface crack
// (the shape of FULL's seeds) in a plate under tension: K_I at the deepest front node against
// Newman & Raju per ring count.
#include <btFracture/bem/CrackSystem.h>
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/FractureSolver.h>
#include <btFracture/fracture/ReferenceCracks.h>
#include <btFracture/fracture/StressIntensity.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

const Material kMaterial(1e9, 0.3, 1000.0, 1e7, 1e6, 2.0, "validation");
// Elements along the crack depth, as in tests/crack (a few seconds per case).
constexpr int kEdgeCrackElements = 4, kNotchedBeamElements = 8;

void metric(const std::string& name, double value) {
    std::printf("METRIC %s %.4f ratio\n", name.c_str(), value);
    std::fflush(stdout);
}

// K_I at mid-thickness of a surface-breaking through crack: FULL's relative to the handbook
// value (`fullMetric`), EST's relative to FULL's (`estMetric`).
void surfaceCrack(const SurfaceCrackCase& c, const std::string& fullMetric, const std::string& estMetric) {
    const SurfaceCrackResult r = solveSurfaceCrack(c, kMaterial);
    std::printf(
        "%s: %d surface triangles, %d crack unknowns, K_I FULL %.5g, EST %.5g (%+.1f %% of FULL), "
        "handbook %.5g\n",
        c.name.c_str(), r.surfaceTriangles, r.crackUnknowns, r.KI, r.estimatedKI,
        100 * (r.estimatedKI / r.KI - 1.0), c.exactKI);
    metric(fullMetric, std::abs(r.KI / c.exactKI - 1.0));
    metric(estMetric, std::abs(r.estimatedKI / r.KI - 1.0));
}

// The edge crack (a/b = `ratio`) grown `steps` steps by FULL and by EST under the same tension
// (tiny toughness, full-length steps of 0.6 h with h the sheet's element size, as the growth
// tests): per step, the mid-thickness front node's depth and K_I of each method, FULL's against
// the handbook value at that depth; returns the worst |EST / FULL - 1| after a step.
double growingEdgeCrack(double ratio, int steps) {
    const SurfaceCrackCase c = edgeCrackCase(ratio, kEdgeCrackElements);
    const ElasticSolver solver{SurfaceMesh(c.body), kMaterial};
    const Material growing(kMaterial.youngsModulus(), kMaterial.poissonRatio(), kMaterial.density(), 1e7, 1e3,
                           2.0, "growing");
    const Eigen::VectorXd q = c.tractions(solver.mesh());
    struct Sample {
        double depth, KI;
    };
    auto grow = [&](FractureMethod method) {
        FractureSettings fs = growthSettings(method);
        fs.crackElementSize = c.along[1] - c.along[0];
        FractureSolver fracture(solver, MaterialField(growing), fs);
        addSurfaceCrackSheet(fracture.cracks(), c, solver.mesh());
        fracture.beginEvent(q);
        std::vector<Sample> out;
        for (int i = 0; i <= steps; ++i) {
            const FrontSifs& f = midThicknessSifs(fracture.frontSifs(), c, solver.mesh());
            out.push_back({(f.position + solver.mesh().offset() - c.origin).dot(c.U), f.KI});
            if (i < steps && fracture.step(i).advancedNodes == 0) break;
        }
        return out;
    };
    const std::vector<Sample> full = grow(FractureMethod::Full), est = grow(FractureMethod::Estimated);
    double worst = 0.0;
    for (std::size_t i = 0; i < std::min(full.size(), est.size()); ++i) {
        const double e = est[i].KI / full[i].KI - 1.0;
        std::printf(
            "%s grown, step %zu: depth FULL %.4f m, EST %.4f m; K_I FULL %.5g (%+.1f %% of handbook), "
            "EST %.5g (%+.1f %% of FULL)\n",
            c.name.c_str(), i, full[i].depth, est[i].depth, full[i].KI,
            100 * (full[i].KI / (kEdgeCrackTension * edgeCrackFactor(full[i].depth, kEdgeCrackPlateWidth)) -
                   1.0),
            est[i].KI, 100 * e);
        std::fflush(stdout);
        if (i > 0) worst = std::max(worst, std::abs(e));
    }
    return worst;
}

struct FrontKI {
    std::vector<double> angle, KI;  // sorted by polar angle
};

FrontKI pennyKI(const ElasticSolver& solver, const Material& material, double a, int rings, double rotation) {
    CrackMesh cracks;
    CrackSystem system(solver, cracks);
    addDiscCrack(system.cracks(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), a, rings, rotation);
    system.update();
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(2, 2) = 1e6;
    const CrackSystem::Solution sol = system.solve(uniformStressTractions(solver.mesh(), sigma));
    auto sifs = displacementCorrelation(system.cracks(), system.nodalOpenings(sol), material);
    for (auto& f : sifs) f.spacing = std::atan2(f.position.y(), f.position.x());  // reuse as angle
    std::sort(sifs.begin(), sifs.end(),
              [](const FrontSifs& x, const FrontSifs& y) { return x.spacing < y.spacing; });
    FrontKI out;
    for (const auto& f : sifs) out.angle.push_back(f.spacing), out.KI.push_back(f.KI);
    return out;
}

// K_I of `f` at polar angle w, linear between neighbouring nodes (periodic).
double interpolate(const FrontKI& f, double w) {
    const int n = static_cast<int>(f.angle.size());
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        double w0 = f.angle[i], w1 = f.angle[j], x = w;
        if (j == 0) w1 += 2 * M_PI;
        if (x < w0) x += 2 * M_PI;
        if (x >= w0 && x <= w1) return f.KI[i] + (f.KI[j] - f.KI[i]) * (x - w0) / (w1 - w0);
    }
    return f.KI[0];
}

// Worst-node K_I error of the penny crack at 8 rings; prints the 4 / 6 / 8-ring table.
double pennyWorstNodeError() {
    const double a = 0.05;
    const ElasticSolver solver(SurfaceMesh(pennyCrackCube(a)), kMaterial);
    const double exact = pennyCrackSifs(1e6, a, M_PI / 2, kMaterial.poissonRatio()).KI;
    double worst8 = 0.0;
    for (int rings : {4, 6, 8}) {
        const FrontKI straight = pennyKI(solver, kMaterial, a, rings, 0.0);
        const FrontKI turned = pennyKI(solver, kMaterial, a, rings, M_PI / 6);
        double mean = 0.0, worst = 0.0, turn = 0.0;
        for (double K : straight.KI) {
            mean += K / exact / straight.KI.size();
            worst = std::max(worst, std::abs(K / exact - 1.0));
        }
        for (std::size_t i = 0; i < turned.KI.size(); ++i)
            turn = std::max(turn, std::abs(turned.KI[i] / interpolate(straight, turned.angle[i]) - 1.0));
        std::printf(
            "penny %d rings: %zu front nodes, K_I mean %+.2f %%, worst node %.2f %%, 30-degree turn %.2f "
            "%%\n",
            rings, straight.KI.size(), 100 * (mean - 1.0), 100 * worst, 100 * turn);
        if (rings == 8) worst8 = worst;
    }
    return worst8;
}

// The crack finer than the BEM surface: the penny in a cube of 16 x 16 cells per face (BEM edge
// a / 2) at 2, 4 and 6 rings (h = BEM edge, / 2, / 3); prints mean and worst-node K_I errors and
// returns the worst node's at h = BEM edge / 3.
double pennyFinerThanSurfaceError() {
    const double a = 0.05;
    const double exact = pennyCrackSifs(1e6, a, M_PI / 2, kMaterial.poissonRatio()).KI;
    const ElasticSolver solver(SurfaceMesh(pennyCrackCube(a, 16)), kMaterial);
    double worst = 0.0;
    for (int rings : {2, 4, 6}) {
        const FrontKI k = pennyKI(solver, kMaterial, a, rings, 0.0);
        double mean = 0.0;
        worst = 0.0;
        for (double K : k.KI) {
            mean += K / exact / k.KI.size();
            worst = std::max(worst, std::abs(K / exact - 1.0));
        }
        std::printf(
            "penny %d rings, h = BEM edge / %d (%d surface triangles): K_I mean %+.2f %%, worst node %.2f "
            "%%\n",
            rings, rings / 2, solver.mesh().triangleCount(), 100 * (mean - 1.0), 100 * worst);
        std::fflush(stdout);
    }
    return worst;
}

// The edge crack (a/b = `ratio`, 4 surface elements along the depth) with crack elements of the
// surface's size, half and a third of it; returns the K_I error at a third.
double edgeCrackFinerThanSurfaceError(double ratio) {
    double error = 0.0;
    for (int refinement : {1, 2, 3}) {
        const SurfaceCrackCase c = edgeCrackCase(ratio, kEdgeCrackElements, 0.0, refinement);
        const SurfaceCrackResult r = solveSurfaceCrack(c, kMaterial);
        error = r.KI / c.exactKI - 1.0;
        std::printf("%s, crack h = surface h / %d: %d crack unknowns, K_I %+.1f %% of exact\n",
                    c.name.c_str(), refinement, r.crackUnknowns, 100 * error);
        std::fflush(stdout);
    }
    return std::abs(error);
}

// The semicircular surface crack at 4, 6 and 8 rings; returns the K_I error at 8.
double semicircularCrackError() {
    double error = 0.0;
    for (int rings : {4, 6, 8}) {
        const SemicircularCrackResult r = solveSemicircularCrack(rings, kMaterial);
        error = r.deepestKI / r.exactKI - 1.0;
        std::printf(
            "semicircular surface crack, %d rings: %d surface triangles, %d crack unknowns (%d on the "
            "mouth), K_I deepest %+.1f %% of Newman-Raju\n",
            rings, r.surfaceTriangles, r.crackUnknowns, r.mouthNodes, 100 * error);
        std::fflush(stdout);
    }
    return std::abs(error);
}

}  // namespace

int main() {
    const std::vector<std::function<void()>> cases = {
        [] {
            surfaceCrack(edgeCrackCase(0.2, kEdgeCrackElements), "edge_crack_error_0p2",
                         "est_vs_full_edge_crack_0p2");
        },
        [] {
            surfaceCrack(edgeCrackCase(0.4, kEdgeCrackElements), "edge_crack_error_0p4",
                         "est_vs_full_edge_crack_0p4");
        },
        [] { surfaceCrack(notchedBeamCase(kNotchedBeamElements), "senb_error", "est_vs_full_senb"); },
        [] { metric("est_vs_full_growing_edge_crack", growingEdgeCrack(0.2, 5)); },
        [] { metric("penny_worst_node_error_8rings", pennyWorstNodeError()); },
        [] { metric("penny_worst_node_error_h_third_of_bem_edge", pennyFinerThanSurfaceError()); },
        [] { metric("edge_crack_error_0p2_h_third_of_bem_edge", edgeCrackFinerThanSurfaceError(0.2)); },
        [] { metric("semicircular_crack_error_8rings", semicircularCrackError()); },
    };
    for (const auto& c : cases) c();
    return 0;
}
