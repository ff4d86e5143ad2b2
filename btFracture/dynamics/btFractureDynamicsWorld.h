// SPDX-License-Identifier: Zlib
#pragma once
// A btDiscreteDynamicsWorld in which btFractureRigidBody bodies break (paper §5).
//
// Why a subclass and not a tick callback on any world: rolling a step back and replaying it
// (§5.2) needs the body states from before the step, the step itself and a second run of it
// inside one stepSimulation() call, and it must not steal the app's single internal tick
// callback slot. Overriding internalSingleStepSimulation() gives exactly that; apps change one
// type name (btDiscreteDynamicsWorld -> btFractureDynamicsWorld) and keep everything else.
//
// Per internal step, when fracture is enabled, an engine is set and at least one
// btFractureRigidBody is in the world:
//  1. snapshot poses, velocities and sleeping states of the non-static bodies (reused storage);
//  2. run Bullet's step unchanged;
//  3. scan the contact manifolds once: for every solved contact point (island awake, distance
//     within the processing threshold) of a fracturable body, add m_appliedImpulse to that body's
//     sum. Manifolds without a fracturable body cost two tag compares; nothing is allocated.
//  4. Cheap trigger: bodies whose sum stays under settings().impulseThreshold are done. For the
//     others, the contacts are converted to BodyContact (body frame; approach speed from the
//     pre-step velocities, i.e. before the solver changed them; Hertz duration, HertzContact.h,
//     with curvatures from FractureEngine::meanCurvature or, for plain bodies, from their Bullet
//     shape, ContactCurvature.h; materials: the body's, or defaultMaterial() for plain bodies)
//     and FractureEngine::fracture() runs.
//  5. If any body broke: restore the snapshot, remove the parents (Bullet drops their contact
//     manifolds with their broadphase pairs), add the fragments with the parent's pre-step rigid
//     motion (v + w x r, same w), push overlapping fragments apart (FragmentSeparation.h),
//     tell the listeners, and replay the step with fracture suppressed. Pairs created in the
//     replay (the fragments') use Bullet's multi-point convex contacts (3 perturbation
//     iterations) so that a resting fragment starts with a full manifold instead of sinking and
//     tipping on a single point; existing pairs are not affected.
// Fragments take the parent's continuous collision settings scaled by their size; fragments of a
// parent without them get continuous collision once they move more than half their size (cube
// root of the volume) in a step, with a swept sphere of a fifth of it: small fast chips would
// otherwise pass through the ground.
// Opt-in (setFragmentSleeping): fragments sleep by their size (FragmentSleeping.h), thresholds
// scaled to it, asleep once still for 0.1 s, instead of Bullet's 0.8 m/s and 2 s, in islands of
// touching bodies (ContactIslandManager.h) instead of Bullet's islands of nearby ones.
// With fracture disabled, no engine, or no btFractureRigidBody added, a step is Bullet's step.
//
// Spin: before Bullet integrates a step, each fragment's angular velocity is limited to the
// rotation the step performs (pi/4 per step, SpinLimit.h), so that the contact solver does not
// meet contacts with spin the body never turns by; counted in FractureStatistics::spinsLimited.
//
// Penetration recovery: fragments can start overlapping their neighbours where their convex
// collision pieces could not be cut apart or pushed far enough (FragmentSeparation.h). Bullet's
// default turns penetrations shallower than btContactSolverInfo::m_splitImpulsePenetrationThreshold
// (4 cm) into velocity (Baumgarte), which launches fragments. So while the world holds fragments
// (and in every replayed step) each step runs with split impulse (position recovery without
// velocity) for penetrations deeper than splitImpulseDepth() (0.5 mm; resting contacts, which are
// shallower, keep Bullet's Baumgarte); the app's solver info is restored after the step.
//
// Energy audit: every event's FractureEnergyAudit (FractureEnergy.h) follows the breaking body's
// kinetic energy through the swap, the separation push and the replayed step, and the world's
// mechanical energy over energyAuditSteps() steps after it; listeners get it when it completes.
//
// Internal tick callbacks: on a step that fractures, Bullet's pre/post tick callbacks run for the
// discarded step and again for the replay; isReplayingStep() tells them apart.
//
// Ownership: fragments are created and owned by the world while they are in it. Removing a body
// from the world (removeRigidBody / removeCollisionObject) hands a world-owned body to the
// caller, so the usual Bullet clean-up loop (remove, then delete every object) stays correct.
// Bodies still in the world when it is destroyed are deleted by it if it owns them. A parent the
// application added is removed on fracture, not deleted: the listener tells the application,
// which deletes it. A world-owned parent is deleted after the listeners ran.
//
// Dispatcher: when it is a btCollisionDispatcher, btGImpactCollisionAlgorithm is registered so that
// CollisionShapeKind::GImpactMesh shapes collide, and convex pairs that cannot touch skip Bullet's
// convex-convex algorithm (SeparatedConvexPairs).
#include <btFracture/core/Material.h>
#include <btFracture/dynamics/FractureEngine.h>
#include <btFracture/dynamics/FractureListener.h>
#include <btFracture/dynamics/FragmentSleeping.h>
#include <btFracture/dynamics/RigidBodySnapshot.h>

#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace btfracture {

class btFractureRigidBody;
class ContactIslandManager;
class SeparatedConvexPairs;

class btFractureDynamicsWorld : public btDiscreteDynamicsWorld {
public:
    // getDispatchInfo().m_allowedCcdPenetration set by the constructor [m]. Bullet's CCD sweep
    // ignores a hit unless the step carries the body more than this into it; its default 0.04
    // lets millimetre chips, spawned a few millimetres from what their parent touched and at its
    // velocity, pass into the ground. Change it after construction if the units are not metres.
    static constexpr btScalar kAllowedCcdPenetration = btScalar(0.001);

    btFractureDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* pairCache,
                            btConstraintSolver* constraintSolver,
                            btCollisionConfiguration* collisionConfiguration);
    ~btFractureDynamicsWorld() override;

    // The world owns its engine. nullptr (the default) means fracture never happens (logged once).
    void setFractureEngine(std::unique_ptr<FractureEngine> engine);
    FractureEngine* fractureEngine() const { return engine_.get(); }

    // The world switch: false turns all fracture work off (the step is plain Bullet).
    void setFractureEnabled(bool enabled) { enabled_ = enabled; }
    bool isFractureEnabled() const { return enabled_; }

    // Material of bodies that are not btFractureRigidBody, for the Hertz contact duration
    // (default: Material::steel(), i.e. stiff).
    void setDefaultMaterial(const Material& material) { defaultMaterial_ = material; }
    const Material& defaultMaterial() const { return defaultMaterial_; }

    void addFractureListener(FractureListener* listener);
    void removeFractureListener(FractureListener* listener);

    const FractureStatistics& fractureStatistics() const { return stats_; }
    void resetFractureStatistics() { stats_ = FractureStatistics{}; }

    bool isReplayingStep() const { return replaying_; }

    // `enabled` false keeps Bullet's threshold; `depth` [m] > 0.
    void setSplitImpulseForFragments(bool enabled, double depth = 0.0005);
    bool splitImpulseForFragments() const { return splitImpulseForFragments_; }
    double splitImpulseDepth() const { return splitImpulseDepth_; }

    // Fragments' sleeping thresholds scaled to their size, settled ones asleep after
    // sleeping.window (FragmentSleeping.h), islands of touching bodies only
    // (ContactIslandManager.h); `enabled` false (the default) keeps the parent's thresholds,
    // Bullet's global deactivation time and Bullet's islands.
    void setFragmentSleeping(bool enabled, const FragmentSleeping& sleeping = {});
    bool fragmentSleepingEnabled() const { return fragmentSleepingEnabled_; }
    const FragmentSleeping& fragmentSleeping() const { return fragmentSleeping_; }

    // Steps after the replayed step over which an event's energy audit follows the world
    // (default 20; 0: the audit ends with the replayed step).
    void setEnergyAuditSteps(int steps);
    int energyAuditSteps() const { return energyAuditSteps_; }
    // Completes every open energy audit now (listeners hear them): call before reading results
    // at the end of a run.
    void finishEnergyAudits();
    // True while `object` is a fragment the world created and still holds.
    bool ownsBody(const btCollisionObject* object) const;

    // Throw btfracture::Error (and add nothing) for a btFractureRigidBody with a non-finite pose or
    // velocity. A body whose state turns non-finite later never triggers fracture (its impulse
    // sum is NaN) and stays a plain Bullet body.
    void addRigidBody(btRigidBody* body) override;
    void addRigidBody(btRigidBody* body, int group, int mask) override;
    void removeRigidBody(btRigidBody* body) override;
    // Bullet's box update, with the boxes of btFractureRigidBody bodies padded by their own contact
    // breaking threshold instead of Bullet's 2 cm (ContactPad.h).
    void updateAabbs() override;

protected:
    void internalSingleStepSimulation(btScalar timeStep) override;
    void updateActivationState(btScalar timeStep) override;
    // Bullet's CCD sweeps, with the candidates they cannot hit left out (SweepCandidateFilter).
    void integrateTransforms(btScalar timeStep) override;
    void createPredictiveContacts(btScalar timeStep) override;

private:
    struct Event;
    struct OpenAudit;
    void noteAdded(btRigidBody* body);
    void collectTriggeredBodies();
    bool buildContacts(btFractureRigidBody& body, std::vector<BodyContact>& contacts) const;
    void runFractureEvents(btScalar timeStep);
    std::vector<btFractureRigidBody*> spawnFragments(btFractureRigidBody& parent, FractureOutcome& outcome);
    void stepWithFracture(btScalar timeStep);
    void followEnergyAudits(std::size_t count);

    std::unique_ptr<FractureEngine> engine_;
    bool enabled_ = true;
    bool replaying_ = false;
    bool missingEngineLogged_ = false;
    Material defaultMaterial_;
    btCollisionConfiguration* collisionConfiguration_;
    std::unique_ptr<SeparatedConvexPairs> separatedPairs_;
    std::vector<FractureListener*> listeners_;
    FractureStatistics stats_;
    std::uint64_t stepStamp_ = 0;
    int fractureBodies_ = 0;  // btFractureRigidBody instances currently in the world

    RigidBodySnapshot snapshot_;
    std::vector<btFractureRigidBody*> touched_;                // fracturable bodies with contacts this step
    std::vector<btFractureRigidBody*> triggered_;              // ... whose impulse sum reached the threshold
    std::vector<std::unique_ptr<btFractureRigidBody>> owned_;  // fragments in the world, creation order
    std::map<std::string, int> fragmentsOf_;  // fragments made so far per root name (their names' numbers)
    bool splitImpulseForFragments_ = true;
    double splitImpulseDepth_ = 0.0005;  // [m]
    int energyAuditSteps_ = 20;
    bool fragmentSleepingEnabled_ = false;
    FragmentSleeping fragmentSleeping_;
    // Islands of touching bodies while fragment sleeping is on; Bullet's own manager is kept in
    // bulletIslands_ meanwhile and put back.
    std::unique_ptr<ContactIslandManager> contactIslands_;
    btSimulationIslandManager* bulletIslands_ = nullptr;
    std::vector<OpenAudit> audits_;  // energy audits still following the world, in event order
};

}  // namespace btfracture
