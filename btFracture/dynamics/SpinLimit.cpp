// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/SpinLimit.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <LinearMath/btTransformUtil.h>

namespace btfracture {

double integrableSpin(double timeStep) {
    return double(ANGULAR_MOTION_THRESHOLD) / timeStep;
}

double limitSpinToStep(btRigidBody& body, double timeStep) {
    const btVector3 w = body.getAngularVelocity();
    const double speed = double(w.length()), limit = integrableSpin(timeStep);
    if (!(speed > limit)) return 0.0;
    body.setAngularVelocity(w * btScalar(limit / speed));
    return speed;
}

}  // namespace btfracture
