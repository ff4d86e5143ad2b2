// SPDX-License-Identifier: Zlib
#pragma once
// Spin that Bullet can integrate. btTransformUtil::integrateTransform turns a body by at most
// pi/4 per step (ANGULAR_MOTION_THRESHOLD; 47 rad/s at 60 Hz) but keeps the whole angular
// velocity, and the contact solver works with the whole one. A millimetre chip struck by a heavy
// ball spins at hundreds to thousands of rad/s: the solver then meets a contact by spinning the
// chip (v + w x r), the chip turns by a fraction of that and its centre keeps falling, so it sinks
// through the ground step by step. Limiting a fragment's angular velocity to what the step turns
// keeps velocity and motion consistent; the rotational energy above the limit is dissipated.
class btRigidBody;

namespace btfracture {

// Largest angular speed Bullet turns a body by in a step of `timeStep` [s], in rad/s.
double integrableSpin(double timeStep);

// Scales the body's angular velocity down to integrableSpin(timeStep); returns its angular speed
// before [rad/s] when it was larger, 0 otherwise.
double limitSpinToStep(btRigidBody& body, double timeStep);

}  // namespace btfracture
