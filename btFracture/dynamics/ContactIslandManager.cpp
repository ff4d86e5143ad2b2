// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/ContactIslandManager.h>

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace btfracture {

void ContactIslandManager::updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) {
    // Bullet's numbering (STATIC_SIMULATION_ISLAND_OPTIMIZATION): the dynamic bodies in the
    // world's order; static and kinematic ones join no island.
    btCollisionObjectArray& objects = world->getCollisionObjectArray();
    int index = 0;
    for (int i = 0; i < objects.size(); ++i) {
        btCollisionObject* object = objects[i];
        if (!object->isStaticOrKinematicObject()) object->setIslandTag(index++);
        object->setCompanionId(-1);
        object->setHitFraction(btScalar(1));
    }
    initUnionFind(index);
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
        if (manifold->getNumContacts() == 0) continue;
        const btCollisionObject* a = manifold->getBody0();
        const btCollisionObject* b = manifold->getBody1();
        if (a && b && a->mergesSimulationIslands() && b->mergesSimulationIslands())
            getUnionFind().unite(a->getIslandTag(), b->getIslandTag());
    }
}

}  // namespace btfracture
