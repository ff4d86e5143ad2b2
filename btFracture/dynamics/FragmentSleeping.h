// SPDX-License-Identifier: Zlib
#pragma once
// Sleeping for piles of fragments. Bullet puts a body to sleep after it stayed under fixed speed
// thresholds (0.8 m/s, 1 rad/s) for gDeactivationTime (2 s, one global for every world): made
// for metre-sized bodies, and longer than a whole fracture scene, so settled chips kept being
// simulated. Fragments instead get thresholds scaled to their size L (cube root of the volume):
// a fragment is settled once, for `window` seconds in a row, its centre moved slower than
// `travel` L per window and it turned slower than `turn` radians per window. Its island then
// falls asleep when every body in it is settled (Bullet's island rule); a contact with a moving
// body wakes the island. A body in free flight passes under the speed threshold only near the top
// of its arc, for 2 v / g (under 20 ms for v <= 0.1 m/s), far shorter than the window.
class btRigidBody;

namespace btfracture {

struct FragmentSleeping {
    double window = 0.1;  // [s]
    double travel = 0.1;  // fraction of the fragment's size per window
    double turn = 0.05;   // [rad] per window
    // Speed thresholds are clamped to [minimumSpeed, Bullet's 0.8 m/s].
    double minimumSpeed = 0.02;  // [m/s]
};

// Sets the body's sleeping thresholds for a fragment of size `length` [m].
void setFragmentSleepingThresholds(btRigidBody& body, double length, const FragmentSleeping& sleeping);

// After Bullet's activation update: a body that stayed under its thresholds for the window wants
// to sleep (WANTS_DEACTIVATION; Bullet's island manager puts its island to sleep in the next step
// when all of the island wants to). Bodies that cannot sleep (DISABLE_DEACTIVATION) are left alone.
void settleIfStill(btRigidBody& body, const FragmentSleeping& sleeping);

}  // namespace btfracture
