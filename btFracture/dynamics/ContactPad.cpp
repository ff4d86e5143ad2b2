// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/ContactPad.h>

#include <btFracture/dynamics/btFractureRigidBody.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace btfracture {

bool usesRelativeThresholds(const btDispatcher* dispatcher) {
    const auto* collisionDispatcher = dynamic_cast<const btCollisionDispatcher*>(dispatcher);
    return collisionDispatcher && (collisionDispatcher->getDispatcherFlags() &
                                   btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
}

btScalar padFor(const btCollisionObject& object, bool relativeThresholds) {
    if (!relativeThresholds || !btFractureRigidBody::upcast(&object) || !object.getCollisionShape())
        return gContactBreakingThreshold;
    return btMin(gContactBreakingThreshold,
                 object.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
}

btScalar broadphasePad(const btCollisionObject& object) {
    const btFractureRigidBody* body = btFractureRigidBody::upcast(&object);
    return body ? body->broadphasePad() : gContactBreakingThreshold;
}

void paddedAabb(const btCollisionObject& object, bool continuous, btScalar pad, btVector3& aabbMin,
                btVector3& aabbMax) {
    const btCollisionShape& shape = *object.getCollisionShape();
    shape.getAabb(object.getWorldTransform(), aabbMin, aabbMax);
    if (continuous && object.getInternalType() == btCollisionObject::CO_RIGID_BODY &&
        !object.isStaticOrKinematicObject()) {
        btVector3 low, high;
        shape.getAabb(object.getInterpolationWorldTransform(), low, high);
        aabbMin.setMin(low);
        aabbMax.setMax(high);
    }
    const btVector3 widen(pad, pad, pad);
    aabbMin -= widen;
    aabbMax += widen;
}

}  // namespace btfracture
