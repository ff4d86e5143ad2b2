// SPDX-License-Identifier: Zlib
#pragma once
// The seam between the Bullet coupling (btFractureDynamicsWorld) and whatever decides how a body
// breaks. The world calls FractureEngine::fracture() for a body whose summed contact impulses in
// one step reached its threshold; the engine answers with fragments or with nothing. No Bullet
// collision types, OpenVDB or BEM types cross this seam: meshes are btfracture::TriangleMesh,
// vectors are Eigen double precision, frames are the parent body's frame.
//
// Frames: a btFractureRigidBody's body frame has its origin at the centre of mass and its axes
// along the principal axes of inertia; body.mesh() and all BodyContact data are in it.
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/dynamics/BodyContact.h>
#include <btFracture/dynamics/FractureState.h>
#include <btFracture/geometry/FragmentClasses.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace btfracture {

class btFractureRigidBody;

// Counters kept by the world; an engine increments bemBuilds whenever it assembles and factors
// a BEM system (so tests can assert that a body under its threshold builds none).
struct FractureStatistics {
    std::uint64_t steps = 0;             // internal steps with fracture active
    std::uint64_t bodiesChecked = 0;     // fracturable bodies with contacts, summed over steps
    std::uint64_t bodiesTriggered = 0;   // ... whose impulse sum reached the threshold
    std::uint64_t engineCalls = 0;       // FractureEngine::fracture() calls
    std::uint64_t engineFailures = 0;    // calls that threw btfracture::Error (body made unbreakable)
    std::uint64_t fractureEvents = 0;    // calls that returned fragments
    std::uint64_t fragmentsSpawned = 0;  // bodies added in place of their parents
    std::uint64_t replayedSteps = 0;     // steps rolled back and replayed after a fracture
    std::uint64_t spinsLimited = 0;  // fragment steps whose spin was cut to what a step turns (SpinLimit.h)
    std::uint64_t bemBuilds = 0;     // incremented by the engine
    double contactSeconds = 0.0;     // wall time converting triggered bodies' contacts [s]
    double engineSeconds = 0.0;      // wall time in every fracture() call, broken or not [s]
    double swapSeconds = 0.0;        // wall time restoring, swapping and separating [s]
    double maxLoadRatio = 0.0;       // largest K_eff / K_c any crack front met, broken or not

    // The fracture time of the paper's Table 1 (t_f): the engine's input (the triggered bodies'
    // contacts with their Hertz durations and surface curvatures, §5.1), every engine call and
    // the swaps. The rest of a step, the replayed steps included, is rigid-body time.
    double fractureSeconds() const { return contactSeconds + engineSeconds + swapSeconds; }
};

struct FragmentSpec {
    // Collision-resolution closed surface, parent body frame [m] (outward-oriented, as
    // requireClosedSolid accepts).
    TriangleMesh collisionMesh;
    double volume = 0.0;                                     // [m^3], measured on the level set
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();  // parent body frame [m]
    // Inertia tensor about the fragment's centre of mass at the parent's density, parent-frame
    // axes [kg m^2] (= density * unit-density tensor of geometry/MassProperties.h).
    Eigen::Matrix3d inertiaAboutCom = Eigen::Matrix3d::Zero();

    // Volume classes of paper §5.2 (the engine decides; thresholds are its settings).
    enum class Class {
        ConvexHull,         // (a) tiny: btConvexHullShape, never breaks again
        Mesh,               // (b) small: mesh shape, never breaks again
        Breakable,          // (c) large: a fracturable btFractureRigidBody, refracture depth + 1
        KeepsParentSolver,  // (d) > 95 % of the parent: fracturable, takes the parent's FractureState
    };
    Class cls = Class::Mesh;

    // For Breakable: the state the fragment starts with (incomplete cracks, §5.3), may be null.
    // Ignored (must be null) for the other classes; KeepsParentSolver gets the parent's state.
    std::unique_ptr<FractureState> carriedState;
};

// The spec class of a fragment of that volume class.
FragmentSpec::Class fragmentSpecClass(FragmentClass c);

// Where the engine's time went (wall clock [s]); reported to listeners in FractureEventInfo.
struct EngineTimings {
    double bem = 0.0;       // building and solving the elastic system
    double fracture = 0.0;  // SIFs, initiation, crack propagation
    double geometry = 0.0;  // level-set cuts, segmentation, fragment meshes and mass properties
};

struct FractureOutcome {
    std::vector<FragmentSpec> fragments;  // empty: nothing broke, the step stands as it is
    EngineTimings timings;                // optional
    int crackTriangles = 0;               // crack-sheet triangles of the body's BEM, if it has one
    double maxLoadRatio = 0.0;            // largest K_eff / K_c over the call's crack steps
};

class FractureEngine {
public:
    virtual ~FractureEngine() = default;

    // Decides whether `body` breaks under `contacts` (all of its contacts of this step, impulse
    // sum >= its threshold). May create or update body.fractureState() (lazily: BEM solver, level
    // set, cracks) and must increment stats.bemBuilds for every BEM system it builds. Throw
    // btfracture::Error for bad input: the world logs it and makes the body unbreakable.
    virtual FractureOutcome fracture(btFractureRigidBody& body, const std::vector<BodyContact>& contacts,
                                     FractureStatistics& stats) = 0;

    // Mean curvature [1/m] of `body`'s surface near `bodyPoint` (body frame), whose inverse is the
    // body's Hertz radius at a contact (§5.1). The world asks before calling fracture(), for every
    // contact of a triggered body (and for a btFractureRigidBody on the other side). Default: the
    // mesh proxy btFractureRigidBody::meanCurvatureAt; an engine that holds a level set
    // (LevelSetBody::meanCurvature) can answer better.
    virtual double meanCurvature(const btFractureRigidBody& body, const Eigen::Vector3d& bodyPoint) const;
};

}  // namespace btfracture
