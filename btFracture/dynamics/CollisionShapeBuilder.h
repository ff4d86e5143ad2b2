// SPDX-License-Identifier: Zlib
#pragma once
// Bullet collision shapes for btFracture bodies and fragments, built from a closed mesh given in
// the body frame (centre of mass, principal axes), plus the data the shapes point into.
//
// Shape kinds (paper §5.2; FragmentSpec::Class maps onto them in btFractureDynamicsWorld):
//  - ConvexHull: GraphHullShape (a btConvexHullShape whose support queries walk its corner
//    graph). Its hull is shrunk by the collision margin (btConvexHullComputer shrink) so that
//    hull + margin matches the mesh instead of bulging out by one margin: two fragments that
//    share a cut face then touch instead of overlapping. With options.hullMaxVertices > 0 at
//    most that many of the shrunk hull's corners are kept (every hull, also the pieces of a
//    decomposition).
//  - ConvexDecomposition: btCompoundShape of shrunk convex hulls: of HACD clusters (Bullet's
//    libHACD) up to options.decompositionTriangleLimit triangles, of plane-split parts
//    (geometry/SplitDecomposition.h) above it. GImpactMesh only where no piece has volume.
//  - GImpactMesh: btGImpactMeshShape over the triangles (what FractureRB used), decimated to
//    options.gimpactMaxTriangles; the dispatcher needs btGImpactCollisionAlgorithm
//    (btFractureDynamicsWorld registers it).
//
// Choice (bench/bench_fragment_shapes, tori as non-convex fragments, this machine, 2 shared
// cores): a pile of 24 tori (576 triangles each) steps in 4.0 ms with HACD compounds against 10.4
// ms with GImpact; both rest equally still (mean speed 3.3 vs 3.6 mm/s) and none tunnels. HACD
// costs time once per shape and grows fast with the mesh: 0.28 s at 576 triangles, 1.2 s at
// 1024, 3.5-5.4 s at 2304. Plane splits take about 0.09 s at 5,000 triangles (16 pieces); with
// them for the fragments that cannot break, falling_boxes steps its rigid bodies in 37.5 ms
// instead of 76.1 ms with GImpact meshes (docs/rigid-body-time.md; collisionShapeKind in
// FractureBodySettings.h keeps GImpact meshes for bodies that can break). Either kind can be
// forced (kind GImpactMesh, or a larger triangle limit for HACD).
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/ConvexPenetration.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

class btCollisionShape;

namespace btfracture {

enum class CollisionShapeKind { ConvexHull, ConvexDecomposition, GImpactMesh };
const char* toString(CollisionShapeKind kind);

struct CollisionShapeOptions {
    // Collision margin [m]; 0 = automatic: min(0.04, 0.02 * cube root of the mesh volume).
    double margin = 0.0;
    // HACD: largest concavity accepted inside one convex piece, as a fraction of the mesh's
    // bounding-box diagonal, and the largest number of hull vertices per piece.
    double decompositionConcavity = 0.02;
    int decompositionMaxHullVertices = 64;
    // ConvexDecomposition uses HACD up to this many triangles and plane splits
    // (geometry/SplitDecomposition.h) above, with at most splitMaxPieces pieces whose hulls exceed
    // their part's volume by at most splitConcavity times the mesh volume (unless the budget ends).
    int decompositionTriangleLimit = 600;
    int splitMaxPieces = 16;
    double splitConcavity = 0.02;
    bool fitsHacd(std::size_t triangles) const {
        return triangles <= static_cast<std::size_t>(std::max(0, decompositionTriangleLimit));
    }
    // A GImpact mesh above this many triangles collides as the mesh decimated to it
    // (geometry/MeshDecimation.h; 0 = every triangle, negative is an error). Bullet tests each triangle whose
    // box meets the other shape's box, so the cost of a mesh pair grows with its triangle density.
    int gimpactMaxTriangles = 1500;
    // Corners kept per convex hull (geometry/HullSimplification.h; 0 = all, the default). Bullet's
    // convex narrowphase scans every corner per support query; the budgeted hull lies inside the
    // full one, so fragments that did not overlap still do not. Off by default: with 48 corners
    // the bunny_smash scenario's first event adds 1.09 % energy (limit 1 %).
    int hullMaxVertices = 0;
};

// Owns a Bullet collision shape and everything it references (child shapes, vertex arrays).
class CollisionShapeStorage {
public:
    CollisionShapeStorage();
    ~CollisionShapeStorage();
    CollisionShapeStorage(const CollisionShapeStorage&) = delete;
    CollisionShapeStorage& operator=(const CollisionShapeStorage&) = delete;

    btCollisionShape* shape() const { return shape_; }
    CollisionShapeKind kind() const { return kind_; }  // the kind actually built
    double margin() const { return margin_; }
    // The convex pieces as collision sees them (shrunk hull points + margin), body frame; empty
    // for GImpactMesh. Used to separate overlapping fragments (ConvexPenetration.h).
    const std::vector<ConvexPolytope>& convexPieces() const { return pieces_; }
    // Rebuilds the shape from new convex pieces (body frame; one per piece of convexPieces(), each
    // with its margin): fragments whose pieces were cut apart (FragmentSeparation.h). Throws
    // btfracture::Error for a GImpact mesh, a different piece count or a piece without volume.
    void replacePieces(std::vector<ConvexPolytope> pieces);

private:
    friend std::unique_ptr<CollisionShapeStorage> buildCollisionShape(const TriangleMesh&, CollisionShapeKind,
                                                                      const CollisionShapeOptions&);
    struct Impl;
    std::unique_ptr<Impl> impl_;
    btCollisionShape* shape_ = nullptr;
    CollisionShapeKind kind_ = CollisionShapeKind::ConvexHull;
    double margin_ = 0.0;
    std::vector<ConvexPolytope> pieces_;
};

// Throws btfracture::Error naming mesh.name when the mesh is empty or flat, or the decomposition
// yields no piece.
std::unique_ptr<CollisionShapeStorage> buildCollisionShape(const TriangleMesh& bodyFrameMesh,
                                                           CollisionShapeKind kind,
                                                           const CollisionShapeOptions& options = {});

}  // namespace btfracture
