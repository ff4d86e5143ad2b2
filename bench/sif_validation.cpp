// SPDX-License-Identifier: Zlib
// Stress intensity factors of FULL (Eq. 4 and the displacement correlation) against closed
// forms. Penny crack of radius a in a cube of side 8 a under tension normal to it (Kassir & Sih):
// per ring count, the mean and worst-node K_I error and the largest change of a node's K_I when
// the disc pattern is turned by 30 degrees (compared at the same polar angle).
#include <btFracture/bem/CrackSystem.h>
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/fracture/CrackSeed.h>
#include <btFracture/fracture/ReferenceCracks.h>
#include <btFracture/fracture/StressIntensity.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace btfracture;

namespace {

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
    std::sort(sifs.begin(), sifs.end(), [](const FrontSifs& x, const FrontSifs& y) { return x.spacing < y.spacing; });
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

}  // namespace

int main() {
    const Material material(1e9, 0.3, 1000.0, 1e7, 1e6, 2.0, "penny");
    const double a = 0.05;
    const ElasticSolver solver(SurfaceMesh(pennyCrackCube(a)), material);
    const double exact = pennyCrackSifs(1e6, a, M_PI / 2, material.poissonRatio()).KI;
    double worst8 = 0.0;
    for (int rings : {4, 6, 8}) {
        const FrontKI straight = pennyKI(solver, material, a, rings, 0.0);
        const FrontKI turned = pennyKI(solver, material, a, rings, M_PI / 6);
        double mean = 0.0, worst = 0.0, turn = 0.0;
        for (double K : straight.KI) {
            mean += K / exact / straight.KI.size();
            worst = std::max(worst, std::abs(K / exact - 1.0));
        }
        for (std::size_t i = 0; i < turned.KI.size(); ++i)
            turn = std::max(turn, std::abs(turned.KI[i] / interpolate(straight, turned.angle[i]) - 1.0));
        std::printf("penny %d rings: %zu front nodes, K_I mean %+.2f %%, worst node %.2f %%, 30-degree turn %.2f %%\n",
                    rings, straight.KI.size(), 100 * (mean - 1.0), 100 * worst, 100 * turn);
        if (rings == 8) worst8 = worst;
    }
    std::printf("METRIC penny_worst_node_error_8rings %.4f ratio\n", worst8);
    return 0;
}
