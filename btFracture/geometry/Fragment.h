// SPDX-License-Identifier: Zlib
#pragma once
// Fragments: the connected pieces of a level-set body after crack cuts (paper §5.2, §5.3).
// All positions are in the parent body's frame [m]; volumes [m^3].
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/FragmentClasses.h>

#include <memory>
#include <string>
#include <vector>

namespace btfracture {

class LevelSetBody;

// Whether `mesh` can stand for a body of `volume` [m^3] in collisions: at least 4 triangles,
// enclosing at least a tenth of the volume (decimation can flatten a sliver's mesh), measured
// about the body's centre of mass (mesh frame) as the world's own check does.
bool holdsVolume(const TriangleMesh& mesh, double volume, const Eigen::Vector3d& centreOfMass);

struct Fragment {
    std::string name;     // "<parent name>/<index>" for messages
    MassProperties mass;  // measured on the fragment's level set, density 1, parent frame
    double fractionOfOriginal = 0.0;
    double fractionOfParent = 0.0;
    FragmentClass volumeClass = FragmentClass::Breakable;

    // Fine mesh of the fragment's level set: crack faces included, incomplete cracks shown as
    // thin slits (closed, triangulated).
    TriangleMesh visualMesh;
    // Closed manifold mesh of about the requested number of triangles (LevelSetBody::fragments); incomplete
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
