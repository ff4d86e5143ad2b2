// SPDX-License-Identifier: Zlib
// BEM set-up cost against mesh size: assembly, regularisation (K + gamma Q Q^T), Cholesky
// factorisation and one solve, matrix memory, and the factorisation's speed next to a plain
// dense LLT of the same size on this machine. Meshes: geodesic spheres and the bunny remeshed for
// the BEM (remeshForBem), at about 500, 1,000, 2,000 and 4,000 triangles.
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/core/Timer.h>
#include <btFracture/geometry/Remesh.h>
#include <btFracture/io/MeshReader.h>

#include <Eigen/Cholesky>

#include <cstdio>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

struct Row {
    std::string mesh;
    int triangles, unknowns;
    double assembly, regularisation, factorisation, solve, megabytes, factorGflops, plainGflops;
};

double plainLltGflops(int n) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
    Eigen::MatrixXd spd = a * a.transpose();
    spd.diagonal().array() += n;
    Timer timer;
    Eigen::LLT<Eigen::MatrixXd> llt(spd);
    const double seconds = timer.seconds();
    return llt.info() == Eigen::Success ? (double(n) * n * n / 3.0) / seconds / 1e9 : 0.0;
}

Row measure(const std::string& name, const TriangleMesh& mesh, const Material& material) {
    Timer total;
    const ElasticSolver solver{SurfaceMesh(mesh), material};
    const SurfaceMesh& m = solver.mesh();
    Eigen::VectorXd q(3 * m.triangleCount());
    for (int t = 0; t < m.triangleCount(); ++t) q.segment<3>(3 * t) = -1e6 * m.normal(t);
    Timer timer;
    const Eigen::VectorXd u = solver.displacements(q);
    const double solve = timer.seconds();
    const auto& t = solver.timings();
    const int n = 3 * m.nodeCount();
    return {name,
            m.triangleCount(),
            n,
            t.assembly,
            t.regularisation,
            t.factorisation,
            solve,
            solver.matrixBytes() / 1048576.0,
            (double(n) * n * n / 3.0) / t.factorisation / 1e9,
            plainLltGflops(n)};
}

}  // namespace

int main() {
    const Material material = Material::pmma();
    std::vector<Row> rows;
    for (int f : {5, 7, 10, 14}) rows.push_back(measure("sphere", makeGeodesicSphere(0.1, f), material));
    TriangleMesh bunny = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/bunny.obj");
    for (auto& v : bunny.vertices) v *= 0.045;  // 0.44 m tall, as in the demo scenes
    for (int target : {500, 1000, 2000, 4000})
        rows.push_back(measure("bunny", remeshForBem(bunny, target), material));

    std::printf("%-8s %9s %8s %10s %10s %10s %8s %9s %12s %12s\n", "mesh", "triangles", "unknowns",
                "assembly_s", "regul_s", "factor_s", "solve_s", "memory_MB", "factor_GF/s", "plainLLT_GF/s");
    for (const Row& r : rows)
        std::printf("%-8s %9d %8d %10.3f %10.3f %10.3f %8.4f %9.1f %12.1f %12.1f\n", r.mesh.c_str(),
                    r.triangles, r.unknowns, r.assembly, r.regularisation, r.factorisation, r.solve,
                    r.megabytes, r.factorGflops, r.plainGflops);
    const Row& at2k = rows[2];  // the 2,000-triangle sphere
    const Row& bunny2k = rows[6];
    std::printf("METRIC bem_init_2k_s %.3f s\n", at2k.assembly + at2k.regularisation + at2k.factorisation);
    std::printf("METRIC bem_init_bunny_2k_s %.3f s\n",
                bunny2k.assembly + bunny2k.regularisation + bunny2k.factorisation);
    std::printf("METRIC bem_factor_efficiency %.2f fraction\n", at2k.factorGflops / at2k.plainGflops);
    return 0;
}
