// SPDX-License-Identifier: Zlib
#pragma once
// Lets an application hear about fracture events (register with
// btFractureDynamicsWorld::addFractureListener).
#include <btFracture/dynamics/FractureEnergy.h>
#include <btFracture/dynamics/FractureEngine.h>

#include <cstdint>
#include <vector>

namespace btfracture {

class btFractureRigidBody;

struct FractureEventInfo {
    std::uint64_t event = 0;         // the world's event counter (0, 1, ...): FractureEnergyAudit::event
    std::uint64_t step = 0;          // the world's internal step counter at the event
    int contacts = 0;                // contacts handed to the engine
    double impulseSum = 0.0;         // summed normal impulse on the parent [N s]
    double contactDuration = 0.0;    // longest Hertz contact duration of those contacts [s]
    int crackTriangles = 0;          // crack-sheet triangles in the parent's BEM after the event
    double engineSeconds = 0.0;      // wall time inside FractureEngine::fracture()
    EngineTimings engineTimings;     // the engine's own split of that time, if it reports one
    double swapSeconds = 0.0;        // wall time for restoring, swapping and separating (whole step)
    double maxSeparationPush = 0.0;  // largest overlap push applied to a new fragment [m]
};

class FractureListener {
public:
    virtual ~FractureListener() = default;

    // Called after `parent` was removed from the world and `fragments` were added, before the
    // step is replayed. Ownership: if the application added `parent`, it is the application's to
    // delete (after this call returns); if the world created it (an earlier fragment), the world
    // deletes it after all listeners ran. Fragments are owned by the world while they are in it
    // (see btFractureDynamicsWorld). The parent's fracture state (btFractureRigidBody::
    // fractureState: BEM, cracks, level set) is released before this call: the parent breaks no
    // further (added to a world again, it would start without cracks).
    virtual void onFractureEvent(btFractureRigidBody& parent,
                                 const std::vector<btFractureRigidBody*>& fragments,
                                 const FractureEventInfo& info) = 0;

    // Called once per event when its energy audit is complete: after the replayed step and
    // btFractureDynamicsWorld::energyAuditSteps() following steps, or earlier from
    // btFractureDynamicsWorld::finishEnergyAudits().
    virtual void onFractureEnergyAudit(const FractureEnergyAudit& /*audit*/) {}
};

}  // namespace btfracture
