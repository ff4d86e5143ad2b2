// SPDX-License-Identifier: Zlib
#pragma once
// Fragments: the connected pieces of a level-set body after crack cuts (paper §5.2, §5.3).
// All positions are in the parent body's frame [m]; volumes [m^3].
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/TriangleMesh.h>

#include <memory>
#include <string>
#include <vector>

namespace btfracture {

class LevelSetBody;

// Volume classes of §5.2. "Original" is the volume of the body before its first fracture,
// passed from parent to fragments; "parent" is the body that has just broken.
enum class FragmentClass {
    ConvexHull,         // (a) <= convexHullMaxFraction of the original: convex hull, never breaks
    Unbreakable,        // (b) <= unbreakableMaxFraction of the original: (non-convex) mesh, never breaks
    Breakable,          // (c) larger: collision mesh plus a new BEM, breaks again (§5.3)
    KeepsParentSolver,  // (d) breakable and > keepParentSolverFraction of the parent: reuses its BEM
};

const char* fragmentClassName(FragmentClass c);

struct FragmentSettings {
    double convexHullMaxFraction = 0.005;    // of the original volume (§5.2: 0.5 %)
    double unbreakableMaxFraction = 0.02;    // of the original volume (§5.2: 2 %)
    double keepParentSolverFraction = 0.95;  // of the parent's volume (§5.2: 95 %)
    // Pieces smaller than this fraction of the original volume are dropped (logged): they are a
    // few voxels at most and cannot be meshed (FractureRB uses 1e-6 too).
    double dustMaxFraction = 1e-6;
    int collisionTriangles = 2000;  // target triangle count of each fragment's collision mesh

    // Throws btfracture::Error naming the field and value unless
    // 0 <= dust < convexHull <= unbreakable < 1, 0 < keepParentSolver <= 1 and collisionTriangles >= 4.
    void validate() const;
};

// Class of a fragment of volume `volume` from a parent of volume `parentVolume`, both pieces of
// a body whose original volume is `originalVolume` (all [m^3], > 0). Thresholds are inclusive
// upper bounds; (d) applies only to fragments that would otherwise be Breakable.
FragmentClass classifyFragment(double volume, double parentVolume, double originalVolume,
                               const FragmentSettings& settings);

// Whether `mesh` can stand for a body of `volume` [m^3] in collisions: at least 4 triangles,
// enclosing at least a tenth of the volume (decimation can flatten a sliver's mesh).
bool holdsVolume(const TriangleMesh& mesh, double volume);

struct Fragment {
    std::string name;     // "<parent name>/<index>" for messages
    MassProperties mass;  // measured on the fragment's level set, density 1, parent frame
    double fractionOfOriginal = 0.0;
    double fractionOfParent = 0.0;
    FragmentClass volumeClass = FragmentClass::Breakable;

    // Fine mesh of the fragment's level set: crack faces included, incomplete cracks shown as
    // thin slits (closed, triangulated).
    TriangleMesh visualMesh;
    // Closed manifold mesh of about FragmentSettings::collisionTriangles triangles; incomplete
    // cracks are closed up.
    TriangleMesh collisionMesh;
    // Closed outward convex hull of the fragment's surface (for class ConvexHull and for
    // separating overlaps, ConvexPenetration.h); for a piece whose surface does not hold its
    // volume (a flake about a voxel thick meshes to next to nothing), the hull of its voxels.
    TriangleMesh convexHull;

    // Breakable and KeepsParentSolver only (§5.3). surfaceMesh: the closed fine surface
    // (incomplete cracks excluded). A new BEM is not remeshed from it (its sub-voxel wedges along
    // crack rims stall the remesher) but from levelSet->bemSourceMesh().
    // incompleteCracks: ids of the cracks that end inside this fragment, sorted; their sheets
    // and fronts are the caller's data. levelSet: the fragment as a body of its own, with these
    // cracks still cut into it, ready for further cuts.
    TriangleMesh surfaceMesh;
    std::vector<int> incompleteCracks;
    std::shared_ptr<LevelSetBody> levelSet;
};

}  // namespace btfracture
