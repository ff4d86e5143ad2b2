// SPDX-License-Identifier: Zlib
// BEM remeshing speed and quality (geometry/Remesh.h) on the shipped bunny and armadillo. Plain
// table; headline line "METRIC remesh_bunny_2k_s <seconds> s". Times are the best of 3 runs.
#include <btFracture/core/Log.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Timer.h>
#include <btFracture/geometry/MeshQuality.h>
#include <btFracture/geometry/Remesh.h>
#include <btFracture/geometry/SurfaceDistance.h>
#include <btFracture/io/MeshReader.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <string>

using namespace btfracture;

namespace {

// Remeshes `input` at each target and prints one table row per target; returns the time at `timed`.
double table(const char* name, const TriangleMesh& input, std::initializer_list<int> targets, int timed) {
    Eigen::AlignedBox3d box;
    for (const auto& v : input.vertices) box.extend(v);
    const double volume = inspectMesh(input).signedVolume;
    double timedSeconds = 0.0;
    for (int target : targets) {
        TriangleMesh output;
        double best = 1e30;
        for (int run = 0; run < 3; ++run) {
            const Timer timer;
            output = remeshForBem(input, target);
            best = std::min(best, timer.seconds());
        }
        const MeshQuality q = measureQuality(output);
        std::printf("%-10s %7zu %7d %9d %9.3f %9.1f %9.1f %9.1f %10.4f %9.2f\n", name, input.triangles.size(),
                    target, q.triangleCount, best, q.minAngleDegrees, q.meanMinAngleDegrees,
                    q.maxAngleDegrees, hausdorffDistance(input, output) / box.diagonal().norm(),
                    100.0 * (inspectMesh(output).signedVolume / volume - 1.0));
        if (target == timed) timedSeconds = best;
    }
    return timedSeconds;
}

}  // namespace

int main() {
    setLogLevel(LogLevel::Warning);
    const std::string meshes = BTFRACTURE_MESH_DIR;
    std::printf("%-10s %7s %7s %9s %9s %9s %9s %9s %10s %9s\n", "mesh", "input", "target", "triangles",
                "time [s]", "min [deg]", "mean min", "max [deg]", "Hausdorff", "volume %");
    const double bunny2k = table("bunny", readMesh(meshes + "/bunny.obj"), {500, 1000, 2000, 4000}, 2000);
    table("armadillo", readMesh(meshes + "/armadillo.obj"), {500, 1000, 2000, 4000}, 0);
    std::printf(
        "(Hausdorff: relative to the input's bounding-box diagonal; volume: change against the input)\n");
    std::printf("METRIC remesh_bunny_2k_s %.3f s\n", bunny2k);
    return 0;
}
