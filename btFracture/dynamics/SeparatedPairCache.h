// SPDX-License-Identifier: Zlib
#pragma once
// A lower bound on the gap between two convex bodies that are apart, so that Bullet's
// convex-convex algorithm (GJK) can be skipped while they cannot touch (the idea of Bullet's
// compiled-out USE_SEPDISTANCE_UTIL2). The gap along a unit axis n (from body B to body A) is
// measured from the shapes' support points, margins included:
//     g = min_{x in A} x.n - max_{y in B} y.n,
// which is at most their distance. Later it shrinks by at most the bodies' relative motion
// along n plus, for each body, the chord its farthest point (bounding radius r) sweeps when the
// body turns by an angle t: 2 r sin(t/2), with sin(t/2) the length of the vector part of the
// relative rotation quaternion. While this bound exceeds the manifold's contact breaking
// threshold, GJK finds no point within it, so the algorithm would add nothing to an empty
// manifold: skipping its call changes nothing. A pair with manifold points is never skipped
// (the algorithm refreshes and removes them). An algorithm that looks further (Bullet's perturbed
// contacts query turned copies of a body) passes the extra distance as `reach`, added to the
// threshold.
#include <LinearMath/btQuaternion.h>
#include <LinearMath/btVector3.h>

class btCollisionObject;
struct btCollisionObjectWrapper;
class btPersistentManifold;

namespace btfracture {

class SeparatedPairCache {
public:
    // True when the call for (a, b) at their current transforms may be skipped: `manifold` is
    // empty and the gap exceeds its contact breaking threshold plus `reach`. First tried: the gap
    // the bodies' broadphase boxes leave (each widened by its broadphasePad); then
    // the bound from the last measurement; when that no longer holds, the gap is measured again
    // at the current transforms, along the last axis and along the line between the bodies'
    // origins, and when neither clears the threshold, along GJK's separating axis. Convex shapes
    // only.
    bool apart(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b,
               const btPersistentManifold& manifold, btScalar reach = 0);

private:
    bool valid_ = false;
    const btCollisionObject* bodyA_ = nullptr;  // the body the axis points to
    btVector3 axis_{0, 0, 0};
    btScalar gap_ = 0;  // gap along axis_ at the measured transforms [m]
    btVector3 originA_, originB_;
    btQuaternion rotationA_, rotationB_;
    btScalar radiusA_ = 0, radiusB_ = 0;  // bounding radii about the origins [m]
};

}  // namespace btfracture
