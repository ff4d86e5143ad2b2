// SPDX-License-Identifier: Zlib
#pragma once
// The finest of the three resolutions (paper §1, §5.2): a body as an OpenVDB narrow-band
// signed-distance level set, plus a crack grid that holds every crack cut into it at voxel
// resolution. OpenVDB stays behind the pimpl; nothing here needs its headers.
//
// Frame and units: positions are in the frame of the mesh the body was built from (the body
// frame), in metres; distances [m], volumes [m^3], curvature [1/m].
//
// Representation (internal, see LevelSetBody.cpp):
//  - solid: signed distance to the uncut body (negative inside), narrow band of 3 voxels, exact
//    distances to the closest triangle signed by its pseudonormal;
//  - crack grid: signed distance to the union of crack slabs. A crack sheet becomes a slab of
//    1.7 voxels thickness (|distance to the sheet| < 0.85 voxel, as in FractureRB), thick enough
//    that a cut through the body always separates its voxels;
//  - object: solid minus the crack slabs (CSG difference); segmentation runs on it.
// The crack slab is a numerical device: mass properties count the slab as material (a crack
// has no thickness), so the fragments of a cut add up to the uncut body.
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/Fragment.h>

#include <Eigen/Core>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace btfracture {

class LevelSetBody {
public:
    // Default resolution: this many voxels across the longest side of the bounding box. At 128
    // the bunny and armadillo measure volume within 0.1 %, centre of mass within 0.02 voxel and
    // inertia within 0.25 % of their exact polyhedral values (tests/geometry); building costs
    // 0.4 s (bunny) to 1.6 s (armadillo, input check included) and about 30 MB.
    static constexpr int kDefaultVoxelsAcross = 128;
    // ... but at least this many through a thin body's mean thickness 2V/A (a 6 mm pane 60 cm
    // wide: 1.3 voxels at 128 across, its level-set volume 6 % low).
    static constexpr int kDefaultVoxelsThrough = 4;
    // ... and at most this many across the longest side (a thinner body is under-resolved, logged).
    static constexpr int kDefaultMaxVoxelsAcross = 1024;
    // Resolution limit that guards memory: at most this many voxels across the longest side.
    static constexpr int kMaxVoxelsAcross = 4096;

    // Longest bounding-box side of `mesh` / kDefaultVoxelsAcross, or its mean thickness 2V/A /
    // kDefaultVoxelsThrough where that is smaller, but no finer than kDefaultMaxVoxelsAcross [m].
    struct DefaultVoxel {
        double size;         // the default [m]
        double byLength;     // longest side / kDefaultVoxelsAcross [m]
        double byThickness;  // 2V/A / kDefaultVoxelsThrough [m]
        double thickness;    // 2V/A [m]
    };
    static DefaultVoxel defaultVoxel(const TriangleMesh& mesh);
    static double defaultVoxelSize(const TriangleMesh& mesh);

    // Builds the level set of a closed, consistently oriented triangle mesh (core/MeshCheck.h;
    // an inside-out mesh is flipped with a warning) at `voxelSize` [m]. Throws btfracture::Error
    // naming mesh.name if the mesh is not a closed solid, if voxelSize is not finite and > 0, or
    // if it would give more than kMaxVoxelsAcross voxels across.
    LevelSetBody(const TriangleMesh& closedMesh, double voxelSize);
    ~LevelSetBody();
    LevelSetBody(LevelSetBody&&) noexcept;
    LevelSetBody& operator=(LevelSetBody&&) noexcept;
    LevelSetBody(const LevelSetBody&) = delete;
    LevelSetBody& operator=(const LevelSetBody&) = delete;

    const std::string& name() const;
    double voxelSize() const;
    // Volume of the body before its first fracture (§5.2); fragments inherit their parent's.
    double originalVolume() const;

    // Volume, centre of mass and inertia (density 1) of the solid, integrated on the level set:
    // each narrow-band voxel contributes the part of it below the tangent plane of the signed
    // distance (exact for planar surfaces), interior voxels and tiles count whole. Crack slabs
    // count as material (see above).
    const MassProperties& massProperties() const;

    // Signed distance to the cut object's surface at p [m]: negative inside material, positive
    // outside the body or inside a crack slab (trilinear interpolation; the narrow band is +-3
    // voxels wide, farther values are clamped to +-3 voxels).
    double signedDistance(const Eigen::Vector3d& p) const;
    // True if p is inside material that no crack slab has removed.
    bool isInsideObject(const Eigen::Vector3d& p) const;
    // True if p is inside the uncut solid (cracks ignored): where a crack front may still grow.
    bool isInsideSolid(const Eigen::Vector3d& p) const;
    // Outward unit normal of the uncut solid's level sets at p (its distance field's gradient);
    // zero where the gradient vanishes (beyond the narrow band).
    Eigen::Vector3d solidNormal(const Eigen::Vector3d& p) const;
    // True if p is inside the slab of an existing crack.
    bool isInsideCrack(const Eigen::Vector3d& p) const;
    // Id of the crack whose slab contains p, or -1 if p is in no crack slab.
    int crackAt(const Eigen::Vector3d& p) const;

    // Mean curvature H = (k1 + k2) / 2 [1/m] of the cut object's surface near p, positive where
    // the surface is convex (a sphere of radius R gives 1/R). p is first projected onto the
    // surface; H is averaged over the surface voxels within 2 voxels of that point, which
    // smooths the facets of the input mesh. Flat: when |H| < 1 / (10 x bounding-box diagonal)
    // the surface there is flatter than anything the body's own size can resolve and the
    // result is exactly 0. The Hertz contact radius (§5.1) is 1 / H, infinite for 0 (a plane)
    // and negative for a concave surface; callers must handle H == 0 explicitly.
    double meanCurvature(const Eigen::Vector3d& p) const;

    // Fine triangle mesh of the cut object's surface (OpenVDB volumeToMesh at adaptivity 0,
    // quads split along their shorter diagonal), outward oriented. Crack slabs show as slits.
    TriangleMesh visualMesh() const;
    // Closed manifold mesh of the solid (cracks closed) with at most targetTriangles triangles,
    // decimated from the level set's mesh (MeshDecimation.h).
    TriangleMesh collisionMesh(int targetTriangles) const;
    // Closed surface a new BEM of about targetTriangles triangles is remeshed from (§5.3): the
    // solid (incomplete cracks filled, as for mass and collision), rebuilt as a level set with
    // voxels of L / voxelsPerEdge [m] (L: edge length of targetTriangles equilateral triangles
    // tiling the solid's surface; never finer than voxelSize()) and meshed there. At that
    // resolution the sub-voxel wedges that crack sheets leave along the rims of the fine
    // surface, and slivers thinner than a coarse voxel, are gone; the fine surface's wedges make
    // decimated meshes self-intersect and stall the remesher. Throws btfracture::Error naming the
    // body for targetTriangles < 4 or voxelsPerEdge not finite and > 0.
    TriangleMesh bemSourceMesh(int targetTriangles, double voxelsPerEdge) const;

    // Writes the level set to an OpenVDB file at `path`: grids "<name>.object" (the cut object,
    // what fragments are segmented from) and "<name>.cracks" (the union of crack slabs), both
    // signed distances in metres, negative inside. Throws btfracture::Error naming the path when
    // the file cannot be written.
    void writeVdb(const std::string& path) const;

    // Writes a swept crack surface into the crack grid as a slab and removes the slab from the
    // object (CSG difference). `sheet` is any set of triangles in the body frame (it need not
    // be closed or oriented; repeated sweeps of the same crack may overlap). `crackId` >= 0
    // names the crack: the caller's id, reported by crackAt() and Fragment::incompleteCracks.
    // Throws btfracture::Error naming sheet.name for an empty sheet, invalid indices, non-finite
    // vertices or a negative crackId. A sheet that misses the body changes nothing.
    void cutAlongSurface(const TriangleMesh& sheet, int crackId);
    // Ids of all cracks cut so far, sorted.
    std::vector<int> crackIds() const;
    // Gives every crack a new id: newIdOf[old] (a fragment's carried cracks take the ids its
    // crack mesh gives them, §5.3). Throws btfracture::Error naming the body if a crack id is
    // missing from newIdOf.
    void renameCracks(const std::map<int, int>& newIdOf);

    // Connected components of the object after the cuts (6-connected interior voxels, §5.2; the
    // "breadth-first search" of the paper, without FractureRB's one-voxel handle threshold), each with
    // mass properties measured on its own level set, volume class, meshes and convex hull.
    // Crack slab material is split between the two sides of each crack at the sheet, so the
    // fragment volumes add up to massProperties().volume (to a fraction of a voxel layer over
    // the crack, from the voxels along its rim). Incomplete cracks
    // (both sides in the same fragment) are filled for mass, collision and BEM surface and
    // carried over into Fragment::levelSet (§5.3). Sorted by decreasing volume (ties: lowest
    // voxel first). Each collision mesh has about `collisionTriangles` triangles (>= 4). Throws
    // btfracture::Error for invalid settings. With fewer than `minimumPieces` components above
    // the dust size it returns none and builds nothing (2: a caller that only wants pieces that
    // came apart skips meshing a body whose cuts separate nothing yet).
    std::vector<Fragment> fragments(const FragmentSettings& settings, int collisionTriangles,
                                    int minimumPieces = 1) const;

    struct Impl;  // OpenVDB grids (internal/LevelSetGrids.h)

private:
    explicit LevelSetBody(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace btfracture
