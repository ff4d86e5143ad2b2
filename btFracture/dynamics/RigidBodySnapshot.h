// SPDX-License-Identifier: Zlib
#pragma once
// Poses, velocities and sleeping states of a world's non-static rigid bodies at the start of an
// internal step, so that btFractureDynamicsWorld can roll a step back and replay it (§5.2).
// Storage is reused between steps (no allocation once it has grown to the body count).
#include <LinearMath/btAlignedObjectArray.h>
#include <LinearMath/btTransform.h>

#include <vector>

class btCollisionObject;
class btRigidBody;

namespace btfracture {

class RigidBodySnapshot {
public:
    struct Entry {
        btTransform transform;
        btVector3 linearVelocity;
        btVector3 angularVelocity;
        btRigidBody* body;
        btScalar deactivationTime;
        int activationState;
    };

    void capture(const btAlignedObjectArray<btRigidBody*>& bodies);
    // Writes the captured state back (world and interpolation transforms, velocities,
    // activation state and deactivation time) to every captured body.
    void restore() const;
    void clear() { entries_.clear(); }
    // Linear search; meant for the rare fracture path only. nullptr when not captured.
    const Entry* find(const btCollisionObject* body) const;

private:
    std::vector<Entry> entries_;
};

}  // namespace btfracture
