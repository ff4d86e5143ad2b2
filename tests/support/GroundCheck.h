// SPDX-License-Identifier: Zlib
#pragma once
// The end-of-run tunnelling check of the scenario and stability suites (ground plane y = 0):
// during a run a body may dip into the ground - discrete collision, fragments spawned at their
// penetrating parent's pose, a light chip pressed in by a heavy piece - but at the end none may lie
// wholly below it, the top of its bounding box deeper than Bullet's penetration slop (about a mm).
#include <btBulletDynamicsCommon.h>

#include <string>

namespace btfracture::test {

constexpr double kGroundSlop = 0.001;  // [m]

// Empty unless `body` lies wholly below the ground; then what is wrong (for a message that
// starts with the body's name).
inline std::string whollyBelowGround(const btRigidBody& body) {
    btVector3 lo, hi;
    body.getAabb(lo, hi);
    if (!(double(hi.y()) < -kGroundSlop)) return {};
    return " lies wholly below the ground at the end: bounding box y " + std::to_string(lo.y()) + " .. " +
           std::to_string(hi.y()) + " m, v_y = " + std::to_string(body.getLinearVelocity().y()) +
           " m/s, mass " + std::to_string(1.0 / body.getInvMass()) + " kg";
}

}  // namespace btfracture::test
