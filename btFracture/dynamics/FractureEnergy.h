// SPDX-License-Identifier: Zlib
#pragma once
// Mechanical energy of rigid bodies and the energy audit of a fracture event: where the breaking
// body's kinetic energy goes through the swap, the separation push, the replayed step and the
// steps that follow while Bullet resolves what overlap is left (paper §5.2 swaps the parent for
// its fragments with the parent's rigid motion, which keeps momentum and kinetic energy; anything
// the pipeline adds shows as a rise of the world's mechanical energy).
//
// Kinetic energy: 1/2 m v.v + 1/2 w.I w (I in world axes). Mechanical energy: kinetic plus the
// gravitational potential -m g.x of the centre of mass (g the body's own gravity vector). Units: J.
#include <cstdint>

class btDiscreteDynamicsWorld;
class btRigidBody;

namespace btfracture {

double kineticEnergy(const btRigidBody& body);
double potentialEnergy(const btRigidBody& body);
double mechanicalEnergy(const btRigidBody& body);  // kinetic + potential
// Sum of mechanicalEnergy over the world's dynamic bodies (static and kinematic ones have none).
double mechanicalEnergy(const btDiscreteDynamicsWorld& world);

struct FractureEnergyAudit {
    std::uint64_t event = 0;        // FractureEventInfo::event of the audited event
    double bodyKinetic = 0.0;       // the breaking body, state before the step
    double partnersKinetic = 0.0;   // dynamic bodies in contact with it, state before the step
    double swapKinetic = 0.0;       // its fragments with its rigid motion (v + w x r, w), unpushed
    double separatedKinetic = 0.0;  // the fragments after the separation push
    // Gravitational potential energy of the fragments minus the body's: at the body's pose (the
    // fragments' centres of mass against the body's), and after the separation push.
    double swapPotentialGain = 0.0;
    double separatedPotentialGain = 0.0;
    double replayKinetic = 0.0;     // the fragments after the replayed step
    double followingKinetic = 0.0;  // the fragments' largest kinetic energy over the following steps
    int followingSteps = 0;         // steps followed after the replay
    double worldBefore = 0.0;       // the world's mechanical energy before the step
    // Largest rise of the world's mechanical energy above worldBefore, after the replayed step and
    // over the following steps (negative: the world only lost energy, as inelastic contacts do).
    double worldGain = 0.0;
    // worldGain over the kinetic energy the event started with (body + partners); 0 when that is 0.
    double addedFraction() const;
};

}  // namespace btfracture
