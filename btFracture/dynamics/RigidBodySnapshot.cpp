// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/RigidBodySnapshot.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>

namespace btfracture {

void RigidBodySnapshot::capture(const btAlignedObjectArray<btRigidBody*>& bodies) {
    entries_.resize(static_cast<std::size_t>(bodies.size()));
    for (int i = 0; i < bodies.size(); ++i) {
        const btRigidBody* body = bodies[i];
        Entry& e = entries_[static_cast<std::size_t>(i)];
        e.body = bodies[i];
        e.transform = body->getWorldTransform();
        e.linearVelocity = body->getLinearVelocity();
        e.angularVelocity = body->getAngularVelocity();
        e.activationState = body->getActivationState();
        e.deactivationTime = body->getDeactivationTime();
    }
}

void RigidBodySnapshot::restore() const {
    for (const Entry& e : entries_) {
        btRigidBody* body = e.body;
        body->setWorldTransform(e.transform);
        body->setInterpolationWorldTransform(e.transform);
        body->setLinearVelocity(e.linearVelocity);
        body->setAngularVelocity(e.angularVelocity);
        body->setInterpolationLinearVelocity(e.linearVelocity);
        body->setInterpolationAngularVelocity(e.angularVelocity);
        body->forceActivationState(e.activationState);
        body->setDeactivationTime(e.deactivationTime);
        body->updateInertiaTensor();
    }
}

const RigidBodySnapshot::Entry* RigidBodySnapshot::find(const btCollisionObject* body) const {
    for (const Entry& e : entries_)
        if (e.body == body) return &e;
    return nullptr;
}

}  // namespace btfracture
