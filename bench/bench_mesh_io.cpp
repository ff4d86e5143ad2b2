// SPDX-License-Identifier: Zlib
// Mesh loading and checking speed on the shipped meshes, and the rigid-body runner's step rate on
// the Fig. 1 scene. Plain table; headline lines "METRIC <name> <value> <unit>". Best of 5 runs.
#include "BestOf.h"

#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/SelfIntersection.h>
#include <btFracture/core/Timer.h>
#include <btFracture/io/MeshReader.h>
#include <btFracture/io/ObjReader.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

using namespace btfracture;

int main() {
    const std::string meshes = BTFRACTURE_MESH_DIR;
    std::printf("%-10s %9s %11s %11s %13s %11s\n", "mesh", "triangles", "parse [ms]", "check [ms]",
                "self-int [ms]", "load [ms]");
    for (const char* name : {"bunny", "spot", "bowl", "column", "fandisk", "teapot", "armadillo"}) {
        const std::string path = meshes + "/" + name + ".obj";
        const TriangleMesh mesh = readObj(path);
        const double parse = bestOf(5, [&] { readObj(path); });
        const double check = bestOf(5, [&] { inspectMesh(mesh); });
        const double self = bestOf(5, [&] { findSelfIntersections(mesh); });
        const double load = bestOf(5, [&] { readMesh(path); });
        std::printf("%-10s %9zu %11.1f %11.1f %13.1f %11.1f\n", name, mesh.triangles.size(), 1e3 * parse,
                    1e3 * check, 1e3 * self, 1e3 * load);
        std::printf("METRIC mesh_load_%s_ms %.2f ms\n", name, 1e3 * load);
    }
    const Scene scene = readSceneFile(meshes + "/../scenes/column_bunny.json");
    double setup = 1e30, simulate = 1e30;
    for (int run = 0; run < 5; ++run) {
        Timer timer;
        SceneWorld world(scene);
        setup = std::min(setup, timer.seconds());
        timer.restart();
        for (int i = 0; i < scene.world.steps; ++i) world.stepFrame();
        simulate = std::min(simulate, timer.seconds());
    }
    std::printf("METRIC column_bunny_setup_s %.3f s\n", setup);
    std::printf("METRIC column_bunny_rigid_s %.4f s\n", simulate);
    std::printf("METRIC column_bunny_steps_per_s %.0f steps/s\n", scene.world.steps / simulate);
    return 0;
}
