// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/SizeScaledBroadphase.h>

#include <btFracture/dynamics/ContactPad.h>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <stdexcept>

namespace btfracture {

SizeScaledBroadphase::SizeScaledBroadphase(btScalar fraction, btOverlappingPairCache* pairCache)
    : btDbvtBroadphase(pairCache) {
    setFraction(fraction);
}

void SizeScaledBroadphase::setFraction(btScalar fraction) {
    if (!(fraction > 0)) throw std::invalid_argument("SizeScaledBroadphase: the margin fraction must be > 0");
    fraction_ = fraction;
}

void SizeScaledBroadphase::setAabb(btBroadphaseProxy* absproxy, const btVector3& aabbMin,
                                   const btVector3& aabbMax, btDispatcher* dispatcher) {
    auto* proxy = static_cast<btDbvtProxy*>(absproxy);
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    const btScalar pad = object ? broadphasePad(*object) : gContactBreakingThreshold;
    const btVector3 extent = aabbMax - aabbMin - btVector3(1, 1, 1) * (2 * pad);
    const btScalar margin = fraction_ * btMax(extent[extent.maxAxis()], btScalar(0));
    const bool fixedSet = proxy->stage == STAGECOUNT;
    // Bullet's own update when its margin applies, when the leaf still holds the box (nothing
    // moves in the tree) and for a body leaving the fixed set (inserted without a margin).
    if (!(margin < gDbvtMargin) || fixedSet ||
        proxy->leaf->volume.Contain(btDbvtVolume::FromMM(aabbMin, aabbMax))) {
        btDbvtBroadphase::setAabb(absproxy, aabbMin, aabbMax, dispatcher);
        return;
    }
    const btVector3 widen(margin, margin, margin);
    setAabbForceUpdate(absproxy, aabbMin - widen, aabbMax + widen, dispatcher);
    proxy->m_aabbMin = aabbMin;  // the body's box, as Bullet keeps it; the leaf holds the margin
    proxy->m_aabbMax = aabbMax;
}

}  // namespace btfracture
