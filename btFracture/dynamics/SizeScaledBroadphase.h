// SPDX-License-Identifier: Zlib
#pragma once
// Bullet's dynamic AABB tree broadphase with leaves widened in proportion to a body's size.
// btDbvtBroadphase widens a moving body's leaf by gDbvtMargin (5 cm) whenever its box leaves the
// leaf, so that the tree is not updated every step; the pair cache holds every pair whose leaves
// overlap. Made for metre-sized bodies: among centimetre chips a 5 cm margin makes almost every
// chip of a heap a pair of every other, and each pair costs a narrowphase dispatch per step. Here
// a leaf is widened by min(gDbvtMargin, fraction x the body's box size), the box without its
// contact pad (ContactPad.h: what btCollisionWorld::updateSingleAabb or btFractureDynamicsWorld::
// updateAabbs adds to every side). A leaf still holds its body's whole box, so no pair within
// the contact breaking threshold is lost; a smaller leaf is updated more often.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>

namespace btfracture {

class SizeScaledBroadphase : public btDbvtBroadphase {
public:
    // `fraction` > 0 of the body's largest box edge (infinity: Bullet's own leaves, bit for bit);
    // throws std::invalid_argument otherwise.
    explicit SizeScaledBroadphase(btScalar fraction = btScalar(0.25),
                                  btOverlappingPairCache* pairCache = nullptr);

    void setAabb(btBroadphaseProxy* proxy, const btVector3& aabbMin, const btVector3& aabbMax,
                 btDispatcher* dispatcher) override;

    btScalar fraction() const { return fraction_; }
    // For the leaves widened from now on; throws as the constructor does.
    void setFraction(btScalar fraction);

private:
    btScalar fraction_ = btScalar(0.25);
};

}  // namespace btfracture
