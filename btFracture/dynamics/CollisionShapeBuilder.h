#pragma once
// Bullet collision shapes for btFracture bodies and fragments, built from a closed mesh given in
// the body frame (centre of mass, principal axes), plus the data the shapes point into.
//
// Shape kinds (paper §5.2; FragmentSpec::Class maps onto them in btFractureDynamicsWorld):
//  - ConvexHull: btConvexHullShape. Its hull is shrunk by the collision margin
//    (btConvexHullComputer shrink) so that hull + margin matches the mesh instead of bulging out
//    by one margin: two fragments that share a cut face then touch instead of overlapping.
//  - ConvexDecomposition: btCompoundShape of shrunk convex hulls of HACD clusters (Bullet's
//    libHACD). The default for non-convex bodies and fragments: it uses Bullet's convex-convex
//    GJK/EPA and persistent manifolds, so resting contact is as stable as for any convex body,
//    and it needs no extra collision algorithm. HACD costs time once per fragment.
//  - GImpactMesh: btGImpactMeshShape over the triangles (what FractureRB used): no decomposition
//    cost, exact concave surface, but mesh-mesh contacts are slow and jittery, and the dispatcher
//    needs btGImpactCollisionAlgorithm (btFractureDynamicsWorld registers it).
//  bench/bench_fragment_shapes measures the two mesh kinds (shape build time, step time, resting
//  jitter); see its header for the numbers behind this choice.
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/ConvexPenetration.h>

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
};

// Owns a Bullet collision shape and everything it references (child shapes, vertex arrays).
class CollisionShapeStorage {
public:
    CollisionShapeStorage();
    ~CollisionShapeStorage();
    CollisionShapeStorage(const CollisionShapeStorage&) = delete;
    CollisionShapeStorage& operator=(const CollisionShapeStorage&) = delete;

    btCollisionShape* shape() const { return shape_; }
    CollisionShapeKind kind() const { return kind_; }
    double margin() const { return margin_; }
    // The convex pieces as collision sees them (shrunk hull points + margin), body frame; empty
    // for GImpactMesh. Used to separate overlapping fragments with libccd.
    const std::vector<ConvexPolytope>& convexPieces() const { return pieces_; }

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
std::unique_ptr<CollisionShapeStorage> buildCollisionShape(const TriangleMesh& bodyFrameMesh, CollisionShapeKind kind,
                                                            const CollisionShapeOptions& options = {});

}  // namespace btfracture
