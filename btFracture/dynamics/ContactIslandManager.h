// SPDX-License-Identifier: Zlib
#pragma once
// Simulation islands of touching bodies. Bullet joins two bodies into one island as soon as their
// broadphase leaves overlap (5 cm beyond their boxes), so a heap of fragments is one island of
// hundreds of bodies, and an island sleeps only when every body in it is settled: one chip that
// still rocks keeps the whole heap awake. Here two bodies share an island only while their
// manifold holds a contact point (Bullet's world then also joins bodies with predictive contacts
// or constraints between them). A body that comes to touch a sleeping island joins it and wakes
// it, as in Bullet. Used while fragment sleeping is on (btFractureDynamicsWorld::
// setFragmentSleeping): the islands also group the solver's work, so the contact order, and with
// it the rounding of the solve, differs from Bullet's islands.
#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>

namespace btfracture {

class ContactIslandManager : public btSimulationIslandManager {
public:
    void updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) override;
};

}  // namespace btfracture
