// SPDX-License-Identifier: Zlib
#pragma once
// The margin around a body's shape in its broadphase box. Bullet widens every box by
// gContactBreakingThreshold (2 cm; btCollisionWorld::updateSingleAabb) whatever the body's size,
// while a pair's manifold keeps points only within the smaller of the two shapes' own thresholds
// (btCollisionDispatcher::getNewManifold with CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD, Bullet's
// default: 0.02 x the shape's angular motion disc, 0.2 mm for a 1 cm chip). Among millimetre
// chips the 2 cm pads make pairs of bodies a centimetre apart, each dispatched every step. The
// world (btFractureDynamicsWorld::updateAabbs) pads the boxes of btFractureRigidBody bodies by
// their own threshold, at most Bullet's: two bodies closer than their manifold's threshold still
// have overlapping boxes. Other bodies keep Bullet's pad.
#include <LinearMath/btScalar.h>
#include <LinearMath/btVector3.h>

class btCollisionObject;
class btDispatcher;

namespace btfracture {

// True when `dispatcher` gives manifolds the smaller of the two shapes' own thresholds
// (btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD).
bool usesRelativeThresholds(const btDispatcher* dispatcher);

// The pad `object`'s broadphase box should get [m]: for a btFractureRigidBody under relative
// thresholds min(gContactBreakingThreshold, the shape's threshold), otherwise
// gContactBreakingThreshold. The world calls it once per body and box update.
btScalar padFor(const btCollisionObject& object, bool relativeThresholds);

// The pad of the box `object` has in the broadphase [m], at most: the one the world stored with
// the box for a btFractureRigidBody (0 before the world's first box update), Bullet's
// gContactBreakingThreshold for other bodies.
btScalar broadphasePad(const btCollisionObject& object);

// The box btCollisionWorld::updateSingleAabb gives `object` with `pad` instead of
// gContactBreakingThreshold: the shape's box at the world transform, with `continuous` (and a
// moving rigid body) joined with its box at the interpolation transform, each widened by `pad`.
void paddedAabb(const btCollisionObject& object, bool continuous, btScalar pad, btVector3& aabbMin,
                btVector3& aabbMax);

}  // namespace btfracture
