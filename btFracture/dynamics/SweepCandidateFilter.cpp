// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/SweepCandidateFilter.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/dynamics/BulletEigen.h>

#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <LinearMath/btTransformUtil.h>

namespace btfracture {

namespace {

// btContinuousConvexCollision reports a hit once the gap falls below this [m].
constexpr btScalar kAdvancementTolerance = btScalar(0.001);

}  // namespace

SweepCandidateFilter::SweepCandidateFilter(btOverlappingPairCache& cache, btScalar timeStep)
    : cache_(cache), previous_(cache.getOverlapFilterCallback()), timeStep_(timeStep) {
    cache_.setOverlapFilterCallback(this);
}

SweepCandidateFilter::~SweepCandidateFilter() {
    cache_.setOverlapFilterCallback(previous_);
}

bool SweepCandidateFilter::needBroadphaseCollision(btBroadphaseProxy* proxy0,
                                                   btBroadphaseProxy* proxy1) const {
    if (previous_) {
        if (!previous_->needBroadphaseCollision(proxy0, proxy1)) return false;
    } else if (!(proxy0->m_collisionFilterGroup & proxy1->m_collisionFilterMask) ||
               !(proxy1->m_collisionFilterGroup & proxy0->m_collisionFilterMask)) {
        return false;
    }
    ++queries_;
    const btRigidBody* swept =
        btRigidBody::upcast(static_cast<const btCollisionObject*>(proxy1->m_clientObject));
    const auto* candidate = static_cast<const btCollisionObject*>(proxy0->m_clientObject);
    if (!swept || !candidate) return true;
    // The sweep's path as Bullet computes it (btRigidBody::predictIntegratedTransform).
    btTransform predicted;
    btTransformUtil::integrateTransform(swept->getWorldTransform(), swept->getLinearVelocity(),
                                        swept->getAngularVelocity(), timeStep_, predicted);
    const btCollisionShape* shape = candidate->getCollisionShape();
    btVector3 centre;
    btScalar radius;
    shape->getBoundingSphere(centre, radius);
    const btVector3 worldCentre = candidate->getWorldTransform() * centre;
    const btVector3& from = swept->getWorldTransform().getOrigin();
    const btVector3& to = predicted.getOrigin();
    // The advancement's tolerance and a rounding slack relative to the lengths involved (float
    // Bullet: 1e-4 of them).
    const btScalar scale = radius + swept->getCcdSweptSphereRadius() + (to - from).length();
    const btScalar allowance = kAdvancementTolerance + btScalar(1e-4) * scale + btScalar(1e-6);
    const btScalar reach = swept->getCcdSweptSphereRadius() + radius + allowance;
    if (!(radius < btScalar(BT_LARGE_FLOAT))) return true;
    const Eigen::Vector3d c = toEigen(worldCentre);
    const Eigen::Vector3d offset = closestPointOnSegment(c, toEigen(from), toEigen(to)) - c;
    const double distance = offset.norm();
    if (distance > double(reach)) {
        ++rejected_;
        return false;
    }
    // A convex candidate lies below its support plane along n (from its centre to the path's
    // nearest point); the swept sphere stays above min(from.n, to.n) - r.
    if (!shape->isConvex() || !(distance > 1e-9)) return true;
    const btVector3 n = toBullet((offset / distance).eval());
    const btTransform& t = candidate->getWorldTransform();
    const btScalar top =
        t(static_cast<const btConvexShape*>(shape)->localGetSupportingVertex(n * t.getBasis())).dot(n);
    const btScalar bottom = btMin(from.dot(n), to.dot(n)) - swept->getCcdSweptSphereRadius();
    if (bottom - top <= allowance) return true;
    ++rejected_;
    ++rejectedBySupport_;
    return false;
}

}  // namespace btfracture
