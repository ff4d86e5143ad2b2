// SPDX-License-Identifier: Zlib
#pragma once
// Internal to btFracture/geometry: the OpenVDB grids behind LevelSetBody and the helpers its two
// OpenVDB translation units share (LevelSetBody.cpp, LevelSetFragments.cpp). Includes OpenVDB,
// so it must never be included from a public header or from any other file.
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/LevelSetBody.h>

#include <openvdb/openvdb.h>
#include <tbb/task_arena.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace btfracture {
namespace levelset {

using openvdb::Coord;
using openvdb::FloatGrid;
using openvdb::Int32Grid;

// Runs f on one thread; every OpenVDB tool call goes through here. meshToVolume widens its band
// in parallel with tasks reading leaves that others are still updating, so a voxel's closest
// triangle depended on thread timing; with only meshToVolume serial, the refracture chain's
// sixth event still differed between two runs in one process (stability label), so all tools
// run serially. Our own loops over leaves stay parallel: one task per leaf, sums in leaf order.
template <typename F>
auto serially(F&& f) {
    tbb::task_arena arena(1);
    return arena.execute(std::forward<F>(f));
}

constexpr float kHalfWidthVoxels = 3.0f;            // narrow band, each side of the surface
constexpr double kCrackHalfThicknessVoxels = 0.85;  // slab = |distance to sheet| < this
// sqrt(3)/2 rounded up [voxels]: a plane farther than this from a voxel's centre misses the voxel,
// so integrateMass counts no part of a voxel with phi >= this and all of one with phi <= -this.
constexpr double kVoxelHalfDiagonal = 0.8661;

struct CrackTriangle {
    Eigen::Vector3d a, b, c;
    int crackId = -1;
};

// Empty level set (background +3 voxels) with a linear transform of `voxelSize`.
FloatGrid::Ptr makeLevelSet(double voxelSize);

// Volume, centre of mass and inertia (density 1) of phi < 0: each voxel contributes the part of
// it below the tangent plane of phi (exact for planar surfaces), interior tiles exactly.
// Deterministic: independent of the thread count.
MassProperties integrateMass(const FloatGrid& phi);

// object := max(object, -slab) on the slab's active voxels where the solid is inside its narrow
// band: a crack slab removed from the object voxel by voxel. Never makes a voxel more inside than
// the solid, unlike OpenVDB's CSG difference, whose sign flood fill leaked through a thin part and
// marked 5,400 voxels outside the solid as inside (a 4th-generation fragment of the corner case).
void carveSlab(FloatGrid& object, const FloatGrid& solid, const FloatGrid& slab);

// Closed triangle mesh of the level set phi = isovalue [m] (0: the surface), outward oriented;
// adaptivity as in OpenVDB's volumeToMesh (0: one quad per surface voxel face, split into two
// triangles).
TriangleMesh meshFromGrid(const FloatGrid& phi, const std::string& name, double adaptivity = 0.0,
                          double isovalue = 0.0);

// Closed manifold mesh of the zero level set with at most targetTriangles triangles (decimated).
// `fineMesh`, if given, must be meshFromGrid(phi) (saves re-meshing on the fallback path).
TriangleMesh collisionMeshFromGrid(const FloatGrid& phi, int targetTriangles, const std::string& name,
                                   const TriangleMesh* fineMesh);

// Index-space centre of voxel ijk in world units.
inline Eigen::Vector3d voxelCentre(const Coord& ijk, double voxelSize) {
    return Eigen::Vector3d(ijk.x(), ijk.y(), ijk.z()) * voxelSize;
}
inline Coord nearestVoxel(const Eigen::Vector3d& p, double voxelSize) {
    const Eigen::Vector3d q = p / voxelSize;
    return Coord(static_cast<int>(std::floor(q.x() + 0.5)), static_cast<int>(std::floor(q.y() + 0.5)),
                 static_cast<int>(std::floor(q.z() + 0.5)));
}

}  // namespace levelset

struct LevelSetBody::Impl {
    std::string name;
    double voxelSize = 0.0;
    double originalVolume = 0.0;
    double boundingDiagonal = 0.0;  // of the solid [m], sets the flat-curvature threshold
    MassProperties mass;            // of the solid

    levelset::FloatGrid::Ptr solid;          // uncut body
    levelset::FloatGrid::Ptr object;         // solid minus crack slabs
    levelset::FloatGrid::Ptr crack;          // union of crack slabs (negative inside a slab)
    levelset::Int32Grid::Ptr crackTriangle;  // nearest crack triangle (index into crackTriangles)
    std::vector<levelset::CrackTriangle> crackTriangles;

    // Bounding diagonal and object (solid minus `crack` when cracks exist) from `solid`.
    void rebuildObject();
};

}  // namespace btfracture
