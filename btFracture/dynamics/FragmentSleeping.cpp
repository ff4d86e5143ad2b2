// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FragmentSleeping.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <algorithm>

namespace btfracture {

void setFragmentSleepingThresholds(btRigidBody& body, double length, const FragmentSleeping& sleeping) {
    const double speed = std::clamp(sleeping.travel * length / sleeping.window, sleeping.minimumSpeed, 0.8);
    body.setSleepingThresholds(btScalar(speed), btScalar(sleeping.turn / sleeping.window));
}

void settleIfStill(btRigidBody& body, const FragmentSleeping& sleeping) {
    // Bullet's updateDeactivation() adds the step to the deactivation time while the body stays
    // under its thresholds and resets it otherwise.
    if (body.getActivationState() == ACTIVE_TAG && body.getDeactivationTime() >= btScalar(sleeping.window))
        body.setActivationState(WANTS_DEACTIVATION);
}

}  // namespace btfracture
