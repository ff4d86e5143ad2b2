// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/SeparatedPairCache.h>

#include <btFracture/dynamics/ContactPad.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <cfloat>
#include <utility>

namespace btfracture {
namespace {

// min_{x in A} x.n - max_{y in B} y.n for the shapes at their wrappers' transforms.
btScalar gapAlong(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b, const btVector3& n) {
    const auto* shapeA = static_cast<const btConvexShape*>(a.getCollisionShape());
    const auto* shapeB = static_cast<const btConvexShape*>(b.getCollisionShape());
    const btTransform& ta = a.getWorldTransform();
    const btTransform& tb = b.getWorldTransform();
    const btVector3 lowA = ta(shapeA->localGetSupportingVertex(-n * ta.getBasis()));
    const btVector3 highB = tb(shapeB->localGetSupportingVertex(n * tb.getBasis()));
    return lowA.dot(n) - highB.dot(n);
}

// GJK's separating axis (from b to a, not normalised), started from `start` and stopped as soon
// as the shapes are proven more than `limit` apart along it (margins included) or it converged.
// Only a direction: the gap along it is measured again from support points.
btVector3 gjkAxis(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b, btScalar limit,
                  const btVector3& start) {
    const auto* shapeA = static_cast<const btConvexShape*>(a.getCollisionShape());
    const auto* shapeB = static_cast<const btConvexShape*>(b.getCollisionShape());
    struct Ignored : btDiscreteCollisionDetectorInterface::Result {
        void setShapeIdentifiersA(int, int) override {}
        void setShapeIdentifiersB(int, int) override {}
        void addContactPoint(const btVector3&, const btVector3&, btScalar) override {}
    } ignored;
    btVoronoiSimplexSolver simplex;
    btGjkPairDetector gjk(shapeA, shapeB, &simplex, nullptr);  // no penetration solver: apart only
    if (start.length2() > SIMD_EPSILON) gjk.setCachedSeparatingAxis(start);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = a.getWorldTransform();
    input.m_transformB = b.getWorldTransform();
    const btScalar reach = limit + shapeA->getMargin() + shapeB->getMargin();
    input.m_maximumDistanceSquared = reach * reach;
    gjk.getClosestPoints(input, ignored, nullptr);
    return gjk.getCachedSeparatingAxis();
}

btScalar boundingRadius(const btCollisionObjectWrapper& w) {
    btVector3 centre;
    btScalar radius;
    w.getCollisionShape()->getBoundingSphere(centre, radius);
    return centre.length() + radius;
}

// Rounding allowance of the gap and the bound: float support points and transforms carry
// relative errors of a few FLT_EPSILON of the coordinates' size.
btScalar slack(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b, btScalar radiusA,
               btScalar radiusB) {
    const btScalar size = a.getWorldTransform().getOrigin().length() +
                          b.getWorldTransform().getOrigin().length() + radiusA + radiusB;
    return btScalar(64 * FLT_EPSILON) * size;
}

// True when the bodies' broadphase boxes (each the shape's box at its current transform, widened
// by its broadphasePad: btCollisionWorld::updateSingleAabb, btFractureDynamicsWorld::
// updateAabbs) leave a gap wider than `limit` between the shapes: along an axis where the boxes
// are g apart (g < 0: they overlap by -g) the shapes are at least g + both pads apart.
bool boxesApart(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b, btScalar limit) {
    const btCollisionObject& objectA = *a.getCollisionObject();
    const btCollisionObject& objectB = *b.getCollisionObject();
    const btBroadphaseProxy* pa = objectA.getBroadphaseHandle();
    const btBroadphaseProxy* pb = objectB.getBroadphaseHandle();
    if (!pa || !pb) return false;
    btScalar gap = -BT_LARGE_FLOAT;
    for (int k = 0; k < 3; ++k)
        gap = btMax(gap, btMax(pb->m_aabbMin[k] - pa->m_aabbMax[k], pa->m_aabbMin[k] - pb->m_aabbMax[k]));
    const btScalar pads = broadphasePad(objectA) + broadphasePad(objectB);
    return gap + pads > limit * btScalar(1.01) + btScalar(1e-6);
}

// sin of half the angle between two rotations.
btScalar halfAngleSine(const btQuaternion& from, const btQuaternion& to) {
    const btQuaternion d = to * from.inverse();
    return btVector3(d.x(), d.y(), d.z()).length();
}

}  // namespace

bool SeparatedPairCache::apart(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b,
                               const btPersistentManifold& manifold, btScalar reach) {
    if (manifold.getNumContacts() > 0) return valid_ = false;
    const btScalar limit = manifold.getContactBreakingThreshold() + reach;
    if (boxesApart(a, b, limit)) return true;
    if (valid_) {
        const bool swapped = a.getCollisionObject() != bodyA_;
        const btTransform& ta = (swapped ? b : a).getWorldTransform();
        const btTransform& tb = (swapped ? a : b).getWorldTransform();
        const btVector3 relative = (tb.getOrigin() - originB_) - (ta.getOrigin() - originA_);
        const btScalar closing = btMax(btScalar(0), relative.dot(axis_));
        const btScalar turning = 2 * radiusA_ * halfAngleSine(rotationA_, ta.getRotation()) +
                                 2 * radiusB_ * halfAngleSine(rotationB_, tb.getRotation());
        if (gap_ - closing - turning > limit + slack(a, b, radiusA_, radiusB_)) return true;
    }
    // Measure again: the last axis (oriented from b to a) and the line between the origins.
    const btScalar radiusA = boundingRadius(a), radiusB = boundingRadius(b);
    btVector3 best(0, 0, 0);
    btScalar bestGap = -BT_LARGE_FLOAT;
    btVector3 line = a.getWorldTransform().getOrigin() - b.getWorldTransform().getOrigin();
    if (line.length2() > SIMD_EPSILON) {
        line.normalize();
        bestGap = gapAlong(a, b, line);
        best = line;
    }
    if (bodyA_ != nullptr) {
        const btVector3 last = a.getCollisionObject() == bodyA_ ? axis_ : -axis_;
        const btScalar gap = gapAlong(a, b, last);
        if (gap > bestGap) bestGap = gap, best = last;
    }
    const btScalar bound = limit + slack(a, b, radiusA, radiusB);
    if (!(bestGap > bound)) {
        const btVector3 axis = gjkAxis(a, b, bound, best);
        if (axis.length2() > SIMD_EPSILON) {
            const btVector3 unit = axis.normalized();
            const btScalar gap = gapAlong(a, b, unit);
            if (gap > bestGap) bestGap = gap, best = unit;
        }
    }
    bodyA_ = a.getCollisionObject();
    axis_ = best;
    valid_ = bestGap > bound;
    if (!valid_) return false;
    gap_ = bestGap;
    originA_ = a.getWorldTransform().getOrigin();
    originB_ = b.getWorldTransform().getOrigin();
    rotationA_ = a.getWorldTransform().getRotation();
    rotationB_ = b.getWorldTransform().getRotation();
    radiusA_ = radiusA;
    radiusB_ = radiusB;
    return true;
}

}  // namespace btfracture
