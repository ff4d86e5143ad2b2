// SPDX-License-Identifier: Zlib
// The implicit-geometry pipeline of one fracture event on the bunny at ~256 voxels across its
// longest side: level-set build, one crack cut, segmentation into fragments with their mass
// properties, meshes (fine surface, collision mesh, convex hull) and the parent's visual mesh.
// Headline: METRIC fragment_pipeline_s (goal <= 10 s on 2 cores) and the process's peak memory.
// Then the voxel-resolution crack front on the same bunny: a seed in the same plane
// grown by markers until they all stop at the surface, and the cut of the surface they swept.
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/core/Timer.h>
#include <btFracture/fracture/CrackFront.h>
#include <btFracture/fracture/LevelSetFrontQueries.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/io/MeshReader.h>

#include <Eigen/Geometry>

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace btfracture;

// Triangles of each fragment's collision mesh (a body's collisionTriangleTarget in the engine).
constexpr int kCollisionTriangles = 2000;

int main() {
    TriangleMesh bunny = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/bunny.obj");
    bunny.name = "bunny";
    // 15 cm, the real bunny's size, centred on its bounding box.
    Eigen::Vector3d lo = bunny.vertices.front(), hi = lo;
    for (const auto& v : bunny.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double scale = 0.15 / (hi - lo).maxCoeff();
    for (auto& v : bunny.vertices) v = (v - 0.5 * (lo + hi)) * scale;
    const double voxel = 0.15 / 256;

    // An oblique plane through the body, well beyond its outline: two fragments.
    TriangleMesh sheet;
    sheet.name = "oblique crack";
    const Eigen::Vector3d c(0.01, 0.02, 0.0), n = Eigen::Vector3d(0.3, 1.0, 0.2).normalized();
    const Eigen::Vector3d u = n.cross(Eigen::Vector3d::UnitZ()).normalized() * 0.2, w = n.cross(u);
    sheet.vertices = {c - u - w, c + u - w, c + u + w, c - u + w};
    sheet.triangles = {{0, 1, 2}, {0, 2, 3}};

    Timer total;
    Timer stage;
    LevelSetBody body(bunny, voxel);
    const double build = stage.seconds();
    stage.restart();
    body.cutAlongSurface(sheet, 0);
    const double cut = stage.seconds();
    stage.restart();
    const auto fragments = body.fragments(FragmentSettings(), kCollisionTriangles);
    const double segment = stage.seconds();
    stage.restart();
    const TriangleMesh visual = body.visualMesh();
    const double visualMesh = stage.seconds();
    const double pipeline = total.seconds();

    const double exact = computeMassProperties(bunny).volume;
    std::printf("bunny 0.15 m, voxel %.3g m (256 across); level-set volume %.6g m^3 (mesh %.6g, %+.3f %%)\n",
                voxel, body.massProperties().volume, exact, 100 * (body.massProperties().volume / exact - 1));
    std::printf("%-34s %9.3f s\n", "level-set build", build);
    std::printf("%-34s %9.3f s\n", "one cut", cut);
    std::printf("%-34s %9.3f s  (%zu fragments)\n", "segmentation + fragment meshes", segment,
                fragments.size());
    std::printf("%-34s %9.3f s  (%zu triangles)\n", "parent visual mesh", visualMesh,
                visual.triangles.size());
    double sum = 0.0;
    for (const Fragment& f : fragments) {
        sum += f.mass.volume;
        std::printf(
            "  %-12s %6.2f %% of original, %-20s surface %7zu, collision %5zu, hull %4zu triangles, "
            "%zu incomplete crack(s)\n",
            f.name.c_str(), 100 * f.fractionOfOriginal, fragmentClassName(f.volumeClass),
            f.surfaceMesh.triangles.size(), f.collisionMesh.triangles.size(), f.convexHull.triangles.size(),
            f.incompleteCracks.size());
    }
    std::printf("fragment volumes sum to %+.4f %% of the uncut level set\n",
                100 * (sum / body.massProperties().volume - 1));

    // Marker front: hexagonal coarse front growing 4 voxels per step in the crack plane.
    LevelSetBody marked(bunny, voxel);
    const FrontQueries queries = levelSetFrontQueries(marked);
    CoarseFront coarse;
    for (int k = 0; k < 6; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 6;
        const Eigen::Vector3d radial = pmath::cos(a) * u.normalized() + pmath::sin(a) * w.normalized();
        coarse.position[k] = c + 2.0 * voxel * radial;
        coarse.advance[k] = 4.0 * voxel * radial;
        coarse.edges.emplace_back(k, (k + 1) % 6);
    }
    stage.restart();
    CrackFronts fronts(voxel);
    fronts.addSheet(0, coarse, queries);
    int steps = 0, markers = 0;
    for (; steps < 100; ++steps) {  // until no marker moves
        const FrontAdvanceResult r = fronts.advance({{0, coarse}}, queries);
        if (r.substeps == 0) break;
        for (int node : r.arrestedCoarseNodes) coarse.advance[node].setZero();
        for (auto& [node, p] : coarse.position) p += coarse.advance[node];
    }
    for (const MarkerChain& chain : fronts.chains(0)) markers += static_cast<int>(chain.markers.size());
    const double frontSeconds = stage.seconds();
    const int swept = fronts.sweptTriangles();
    TriangleMesh sweptSurface = fronts.takeSwept().at(0);
    sweptSurface.name = "marker crack";
    stage.restart();
    marked.cutAlongSurface(sweptSurface, 0);
    const double markerCut = stage.seconds();
    const auto markerFragments = marked.fragments(FragmentSettings(), kCollisionTriangles);
    std::printf(
        "marker front: %d steps, %d markers at the end, %d swept triangles: %.3f s; their cut %.3f s; "
        "%zu fragments",
        steps, markers, swept, frontSeconds, markerCut, markerFragments.size());
    for (std::size_t k = 0; k < markerFragments.size() && k < fragments.size(); ++k)
        std::printf(" (%+.3f %% vs the planar cut's)",
                    100 * (markerFragments[k].mass.volume / fragments[k].mass.volume - 1));
    std::printf("\n");
    std::printf("METRIC marker_front_s %.3f s\n", frontSeconds);
    std::printf("METRIC marker_cut_s %.3f s\n", markerCut);

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("METRIC fragment_pipeline_s %.3f s\n", pipeline);
    std::printf("METRIC fragment_pipeline_peak_rss_mb %.1f MB\n", usage.ru_maxrss / 1024.0);
    return 0;
}
