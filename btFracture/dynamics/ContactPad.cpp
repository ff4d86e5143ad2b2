// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/ContactPad.h>

#include <btFracture/dynamics/btFractureRigidBody.h>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace btfracture {

btScalar broadphasePad(const btCollisionObject& object, const btDispatcher* dispatcher) {
    const auto* collisionDispatcher = dynamic_cast<const btCollisionDispatcher*>(dispatcher);
    const bool relative =
        collisionDispatcher && (collisionDispatcher->getDispatcherFlags() &
                                btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
    if (!relative || !btFractureRigidBody::upcast(&object) || !object.getCollisionShape())
        return gContactBreakingThreshold;
    return btMin(gContactBreakingThreshold,
                 object.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
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
