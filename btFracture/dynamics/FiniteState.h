// SPDX-License-Identifier: Zlib
#pragma once
// Whether a rigid body's state is finite: NaN or Inf in a pose or velocity spreads to every body
// it touches, so the world refuses such bodies and the runners stop on them.
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cmath>

namespace btfracture {

// True when position, orientation and both velocities are finite (summed in double, so that
// large finite values do not overflow).
inline bool hasFiniteState(const btRigidBody& body) {
    const btTransform& t = body.getWorldTransform();
    const btVector3 v = body.getLinearVelocity(), w = body.getAngularVelocity(), p = t.getOrigin();
    const btQuaternion q = t.getRotation();
    return std::isfinite(double(v.x()) + v.y() + v.z() + w.x() + w.y() + w.z() + p.x() + p.y() + p.z() +
                         q.x() + q.y() + q.z() + q.w());
}

}  // namespace btfracture
