// SPDX-License-Identifier: Zlib
#pragma once
// Per-body fracture settings of a btFractureRigidBody (SI units). With the material, these are
// what a body's fracture depends on; the engine adds its own (BemFractureEngineSettings).
#include <btFracture/core/FractureSettings.h>
#include <btFracture/dynamics/CollisionShapeBuilder.h>

#include <string>

namespace btfracture {

// method and hybridElementThreshold come from FractureMethodSettings.
struct FractureBodySettings : FractureMethodSettings {
    bool fracturable = true;  // false: a plain Bullet body, the world's hook never looks at it
    // Cheap trigger: the fracture engine runs only when the sum of the normal impulses on the
    // body in one step reaches this value [N s].
    double impulseThreshold = 1.0;
    int bemTriangleTarget = 1000;        // BEM mesh resolution [triangles], >= 4
    int collisionTriangleTarget = 5000;  // collision mesh of its fragments [triangles], >= BEM target
    double voxelSize = 0.0;              // level-set voxel size [m]; 0: LevelSetBody::defaultVoxel
    // Generations: an original body has refractureDepth 0, a breakable fragment its parent's + 1
    // (the > 95 % fragment keeps its parent's). A body breaks only while
    // refractureDepth <= maxRefractureDepth.
    int maxRefractureDepth = 3;
    int refractureDepth = 0;
    // Collision shape of a non-convex body and of its non-convex fragments (convex ones always
    // get a btConvexHullShape); see CollisionShapeBuilder.h for the trade-off.
    CollisionShapeKind concaveShapeKind = CollisionShapeKind::ConvexDecomposition;
    CollisionShapeOptions shapeOptions;
    // Seeded spatial variation of this body's strength and toughness (off by default).
    MaterialNoise materialNoise;
};

// Throws btfracture::Error naming `body` and the offending field when a value is out of range.
void validate(const FractureBodySettings& settings, const std::string& body);

// Collision shape kind of a body with these settings and this closed mesh: a convex hull when
// the mesh is convex. A body that can still break and whose mesh is above HACD's triangle limit
// keeps a GImpact mesh: Bullet's contact points on its shape become the fracture loads (Eq. 6),
// and convex pieces put them on hull faces that bridge the mesh's hollows
// (docs/rigid-body-time.md). Else settings.concaveShapeKind.
CollisionShapeKind collisionShapeKind(const FractureBodySettings& settings, const TriangleMesh& mesh);

}  // namespace btfracture
