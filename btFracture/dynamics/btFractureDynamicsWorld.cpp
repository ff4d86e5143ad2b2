// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/btFractureDynamicsWorld.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/BulletEigen.h>
#include <btFracture/dynamics/ContactCurvature.h>
#include <btFracture/dynamics/ContactIslandManager.h>
#include <btFracture/dynamics/ContactPad.h>
#include <btFracture/dynamics/FiniteState.h>
#include <btFracture/dynamics/FractureEnergy.h>
#include <btFracture/dynamics/FragmentSeparation.h>
#include <btFracture/dynamics/HertzContact.h>
#include <btFracture/dynamics/NewPairMultipoint.h>
#include <btFracture/dynamics/SeparatedConvexPairs.h>
#include <btFracture/dynamics/SpinLimit.h>
#include <btFracture/dynamics/SweepCandidateFilter.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <LinearMath/btQuickprof.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <sstream>

namespace btfracture {
namespace {

btFractureRigidBody* fracturable(const btCollisionObject* object) {
    btFractureRigidBody* body = btFractureRigidBody::upcast(const_cast<btCollisionObject*>(object));
    return body && body->isFracturable() ? body : nullptr;
}

// The solver touched this manifold's points in the step just taken: its island was awake and
// both bodies respond to contacts.
bool wasSolved(const btPersistentManifold& manifold) {
    const btCollisionObject* a = manifold.getBody0();
    const btCollisionObject* b = manifold.getBody1();
    return (a->isActive() || b->isActive()) && a->hasContactResponse() && b->hasContactResponse();
}

// The body's solved contacts with static or kinematic objects, unit normals into the body, each
// normal once with every point that has it: the fragments they reach are not separated against
// them, i.e. into the ground (blockedNormals, FragmentSeparation.h).
std::vector<StaticContact> staticContactsOf(btDispatcher& dispatcher, const btCollisionObject& body) {
    std::vector<StaticContact> contacts;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
        const bool isBody0 = manifold->getBody0() == &body;
        if (!isBody0 && manifold->getBody1() != &body) continue;
        const btCollisionObject* other = isBody0 ? manifold->getBody1() : manifold->getBody0();
        if (!other->isStaticOrKinematicObject() || !wasSolved(*manifold)) continue;
        for (int k = 0; k < manifold->getNumContacts(); ++k) {
            const btManifoldPoint& point = manifold->getContactPoint(k);
            if (point.getDistance() > manifold->getContactProcessingThreshold()) continue;
            // Bullet's normal points from body1 to body0.
            const Eigen::Vector3d n = toEigen(isBody0 ? point.m_normalWorldOnB : -point.m_normalWorldOnB);
            if (!(n.norm() > 0.5)) continue;
            const Eigen::Vector3d unit = n.normalized();
            const Eigen::Vector3d at =
                toEigen(isBody0 ? point.getPositionWorldOnA() : point.getPositionWorldOnB());
            auto seen = std::find_if(contacts.begin(), contacts.end(),
                                     [&](const StaticContact& c) { return c.normal.dot(unit) > 1.0 - 1e-9; });
            if (seen == contacts.end()) seen = contacts.insert(contacts.end(), StaticContact{unit, {}});
            seen->points.push_back(at);
        }
    }
    return contacts;
}

// Dynamic bodies with solved contacts with `body` (each once, in manifold order).
std::vector<const btRigidBody*> dynamicContactPartners(btDispatcher& dispatcher,
                                                       const btCollisionObject& body) {
    std::vector<const btRigidBody*> partners;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
        const bool isBody0 = manifold->getBody0() == &body;
        if (!isBody0 && manifold->getBody1() != &body) continue;
        if (manifold->getNumContacts() == 0 || !wasSolved(*manifold)) continue;
        const btRigidBody* other = btRigidBody::upcast(isBody0 ? manifold->getBody1() : manifold->getBody0());
        if (other && !other->isStaticOrKinematicObject() &&
            std::find(partners.begin(), partners.end(), other) == partners.end())
            partners.push_back(other);
    }
    return partners;
}

const char* className(FragmentSpec::Class cls) {
    switch (cls) {
        case FragmentSpec::Class::ConvexHull:
            return "convex hull";
        case FragmentSpec::Class::Mesh:
            return "mesh";
        case FragmentSpec::Class::Breakable:
            return "breakable";
        case FragmentSpec::Class::KeepsParentSolver:
            return "keeps parent solver";
    }
    return "?";
}

// Throws when the engine's fragment is unusable.
void validateSpec(const FragmentSpec& spec, double originalVolume, const std::string& where) {
    std::ostringstream problem;
    const Eigen::Matrix3d& J = spec.inertiaAboutCom;
    if (spec.collisionMesh.vertices.size() < 4 || spec.collisionMesh.triangles.size() < 4)
        problem << "collision mesh has " << spec.collisionMesh.vertices.size() << " vertices and "
                << spec.collisionMesh.triangles.size() << " triangles (need a closed mesh)";
    else if (!(spec.volume > 0.0) || !std::isfinite(spec.volume))
        problem << "volume " << spec.volume << " m^3 (need > 0)";
    else if (spec.volume * (1.0 - btFractureRigidBody::kOriginalVolumeTolerance) > originalVolume)
        problem << "volume " << spec.volume << " m^3 above the original body's " << originalVolume << " m^3";
    else if (!spec.centreOfMass.allFinite())
        problem << "non-finite centre of mass";
    else if (const double v = enclosedVolume(spec.collisionMesh, spec.centreOfMass); !(v > 0.0))
        problem << "collision mesh encloses " << v
                << " m^3 about the fragment's centre of mass (need > 0: closed, normals outward)";
    else if (!J.allFinite() || (J - J.transpose()).norm() > 1e-9 * J.norm())
        problem << "inertia tensor not finite and symmetric";
    else if (spec.carriedState && spec.cls != FragmentSpec::Class::Breakable)
        problem << "carries a FractureState but is of class '" << className(spec.cls)
                << "' (only breakable may)";
    if (problem.tellp() > 0) throw Error(where + ": " + problem.str());
    const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(J).eigenvalues();
    if (!(moments(0) > 0.0) || moments(0) + moments(1) < moments(2) * (1.0 - 1e-6)) {
        std::ostringstream out;
        out << where << ": inertia tensor has principal moments (" << moments.transpose()
            << ") kg m^2, not a physical rigid body (need positive moments obeying the triangle inequality)";
        throw Error(out.str());
    }
}

// While alive (and `active`), penetrations deeper than `depth` are recovered by split impulse;
// the solver info is restored afterwards.
class SplitImpulseBelowDepth {
public:
    SplitImpulseBelowDepth(btContactSolverInfo& info, bool active, double depth)
        : info_(info),
          active_(active),
          split_(info.m_splitImpulse),
          threshold_(info.m_splitImpulsePenetrationThreshold) {
        if (!active_) return;
        info_.m_splitImpulse = 1;
        // Bullet uses split impulse where the (negative) penetration is below the threshold.
        info_.m_splitImpulsePenetrationThreshold = btScalar(-depth);
    }
    ~SplitImpulseBelowDepth() {
        if (!active_) return;
        info_.m_splitImpulse = split_;
        info_.m_splitImpulsePenetrationThreshold = threshold_;
    }
    SplitImpulseBelowDepth(const SplitImpulseBelowDepth&) = delete;
    SplitImpulseBelowDepth& operator=(const SplitImpulseBelowDepth&) = delete;

private:
    btContactSolverInfo& info_;
    bool active_;
    int split_;
    btScalar threshold_;
};

Eigen::Matrix3d worldInertia(const btRigidBody& body) {
    const Eigen::Matrix3d R = toEigen(body.getWorldTransform().getBasis());
    return R * toEigen(body.getInvInertiaDiagLocal()).cwiseInverse().asDiagonal() * R.transpose();
}

// Kinetic energy of `fragments` moving rigidly with `parent`: v + w x (x_f - x_parent), w.
double rigidMotionKineticEnergy(const std::vector<btFractureRigidBody*>& fragments,
                                const btRigidBody& parent) {
    const Eigen::Vector3d origin = toEigen(parent.getWorldTransform().getOrigin());
    const Eigen::Vector3d v = toEigen(parent.getLinearVelocity()), w = toEigen(parent.getAngularVelocity());
    double sum = 0.0;
    for (const btFractureRigidBody* f : fragments) {
        const Eigen::Vector3d u = v + w.cross(toEigen(f->getWorldTransform().getOrigin()) - origin);
        sum += 0.5 * u.squaredNorm() / double(f->getInvMass()) + 0.5 * w.dot(worldInertia(*f) * w);
    }
    return sum;
}

// Gravitational potential energy of fragments not yet in the world (they get the world's gravity
// when added): -m g.x under the parent's gravity g.
double potentialEnergy(const std::vector<btFractureRigidBody*>& fragments, const btVector3& g) {
    double sum = 0.0;
    for (const btFractureRigidBody* f : fragments) {
        const btVector3 x = f->getCenterOfMassPosition();
        sum -=
            (double(g.x()) * x.x() + double(g.y()) * x.y() + double(g.z()) * x.z()) / double(f->getInvMass());
    }
    return sum;
}

double summedKineticEnergy(const std::vector<const btRigidBody*>& bodies) {
    double sum = 0.0;
    for (const btRigidBody* b : bodies) sum += kineticEnergy(*b);
    return sum;
}

// Moves the fragments by their separation pushes and gives them the parent's pre-step rigid
// motion. Without pushes: v_f = v + w x (x_f - x_parent), w_f = w. With pushes the fragments'
// common centre moves to X' and a rigid motion about the old centre would change the angular
// momentum at first order in the push; so the common angular velocity becomes w' = I'^-1 I_0 w
// (I_0, I': the fragments' inertia about their common centre before and after the pushes) and
// v_f = V + w' x (x_f - X'), V the velocity of the old common centre. Linear momentum and angular
// momentum about the centre of mass are then exactly those the unpushed fragments carried.
void assignParentMotion(const std::vector<btFractureRigidBody*>& fragments,
                        const std::vector<Eigen::Vector3d>& pushes, const btRigidBody& parent) {
    const Eigen::Vector3d parentOrigin = toEigen(parent.getWorldTransform().getOrigin());
    const Eigen::Vector3d v = toEigen(parent.getLinearVelocity());
    const Eigen::Vector3d w = toEigen(parent.getAngularVelocity());
    const std::size_t n = fragments.size();
    std::vector<double> mass(n);
    std::vector<Eigen::Vector3d> before(n), after(n);
    double total = 0.0;
    Eigen::Vector3d centreBefore = Eigen::Vector3d::Zero(), centreAfter = Eigen::Vector3d::Zero();
    bool pushed = false;
    for (std::size_t k = 0; k < n; ++k) {
        mass[k] = 1.0 / double(fragments[k]->getInvMass());
        before[k] = toEigen(fragments[k]->getWorldTransform().getOrigin());
        after[k] = before[k] + pushes[k];
        pushed = pushed || pushes[k] != Eigen::Vector3d::Zero();
        total += mass[k];
        centreBefore += mass[k] * before[k];
        centreAfter += mass[k] * after[k];
    }
    centreBefore /= total;
    centreAfter /= total;
    const Eigen::Vector3d V = v + w.cross(centreBefore - parentOrigin);
    Eigen::Vector3d spin = w;
    if (pushed) {
        Eigen::Matrix3d inertiaBefore = Eigen::Matrix3d::Zero(), inertiaAfter = Eigen::Matrix3d::Zero();
        for (std::size_t k = 0; k < n; ++k) {
            const Eigen::Matrix3d own = worldInertia(*fragments[k]);
            const Eigen::Vector3d r0 = before[k] - centreBefore, r1 = after[k] - centreAfter;
            inertiaBefore +=
                own + mass[k] * (r0.squaredNorm() * Eigen::Matrix3d::Identity() - r0 * r0.transpose());
            inertiaAfter +=
                own + mass[k] * (r1.squaredNorm() * Eigen::Matrix3d::Identity() - r1 * r1.transpose());
        }
        spin = inertiaAfter.ldlt().solve(inertiaBefore * w);
    }
    for (std::size_t k = 0; k < n; ++k) {
        btFractureRigidBody& f = *fragments[k];
        btTransform t = f.getWorldTransform();
        const Eigen::Vector3d centre = pushed ? after[k] : before[k];
        const Eigen::Vector3d velocity = pushed ? Eigen::Vector3d(V + spin.cross(after[k] - centreAfter))
                                                : Eigen::Vector3d(v + w.cross(before[k] - parentOrigin));
        t.setOrigin(toBullet(centre));
        f.setWorldTransform(t);
        f.setInterpolationWorldTransform(t);
        f.setLinearVelocity(toBullet(velocity));
        f.setAngularVelocity(toBullet(spin));
        f.setInterpolationLinearVelocity(toBullet(velocity));
        f.setInterpolationAngularVelocity(toBullet(spin));
        f.updateInertiaTensor();
    }
}

}  // namespace

struct btFractureDynamicsWorld::Event {
    btFractureRigidBody* parent;
    FractureOutcome outcome;
    FractureEventInfo info;
    std::vector<btFractureRigidBody*> fragments;
    std::vector<StaticContact> staticContacts;  // the parent's contacts with static geometry
    std::vector<const btRigidBody*> partners;   // dynamic bodies in contact with the parent
    FractureEnergyAudit energy;
    double bodyPotential = 0.0;  // the parent's, before the step
};

struct btFractureDynamicsWorld::OpenAudit {
    FractureEnergyAudit audit;
    std::vector<const btRigidBody*> fragments;  // those still in the world
    int stepsLeft = 0;
};

btFractureDynamicsWorld::btFractureDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* pairCache,
                                                 btConstraintSolver* constraintSolver,
                                                 btCollisionConfiguration* collisionConfiguration)
    : btDiscreteDynamicsWorld(dispatcher, pairCache, constraintSolver, collisionConfiguration),
      defaultMaterial_(Material::steel()),
      collisionConfiguration_(collisionConfiguration) {
    getDispatchInfo().m_allowedCcdPenetration = kAllowedCcdPenetration;
    if (auto* collisionDispatcher = dynamic_cast<btCollisionDispatcher*>(dispatcher)) {
        btGImpactCollisionAlgorithm::registerAlgorithm(collisionDispatcher);
        if (collisionConfiguration)
            separatedPairs_ =
                std::make_unique<SeparatedConvexPairs>(*collisionDispatcher, *collisionConfiguration);
    }
}

btFractureDynamicsWorld::~btFractureDynamicsWorld() {
    for (auto& body : owned_) btDiscreteDynamicsWorld::removeRigidBody(body.get());
    owned_.clear();
    if (contactIslands_) m_islandManager = bulletIslands_;  // Bullet frees its own
}

void btFractureDynamicsWorld::setFractureEngine(std::unique_ptr<FractureEngine> engine) {
    engine_ = std::move(engine);
    missingEngineLogged_ = false;
}

void btFractureDynamicsWorld::addFractureListener(FractureListener* listener) {
    if (listener && std::find(listeners_.begin(), listeners_.end(), listener) == listeners_.end())
        listeners_.push_back(listener);
}

void btFractureDynamicsWorld::removeFractureListener(FractureListener* listener) {
    listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), listener), listeners_.end());
}

bool btFractureDynamicsWorld::ownsBody(const btCollisionObject* object) const {
    return std::any_of(owned_.begin(), owned_.end(), [object](const auto& b) { return b.get() == object; });
}

void btFractureDynamicsWorld::noteAdded(btRigidBody* body) {
    btFractureRigidBody* f = btFractureRigidBody::upcast(body);
    if (!f) return;
    f->broadphasePad_ = 0;  // the box Bullet made on adding the body has none
    if (!f->inFractureWorld_) {
        f->inFractureWorld_ = true;
        ++fractureBodies_;
    }
}

namespace {

// A breakable body must enter the world with a finite pose and velocity: NaN would spread to
// every body it touches. Throws btfracture::Error naming the body.
void requireFiniteState(const btRigidBody* body) {
    const btFractureRigidBody* f = btFractureRigidBody::upcast(body);
    if (f && !hasFiniteState(*f))
        throw Error(f->name() +
                    ": non-finite position, orientation or velocity (NaN or Inf); not added to the world");
}

}  // namespace

void btFractureDynamicsWorld::addRigidBody(btRigidBody* body) {
    requireFiniteState(body);
    btDiscreteDynamicsWorld::addRigidBody(body);
    noteAdded(body);
}

void btFractureDynamicsWorld::addRigidBody(btRigidBody* body, int group, int mask) {
    requireFiniteState(body);
    btDiscreteDynamicsWorld::addRigidBody(body, group, mask);
    noteAdded(body);
}

void btFractureDynamicsWorld::removeRigidBody(btRigidBody* body) {
    btDiscreteDynamicsWorld::removeRigidBody(body);
    for (OpenAudit& open : audits_)
        open.fragments.erase(std::remove(open.fragments.begin(), open.fragments.end(), body),
                             open.fragments.end());
    if (btFractureRigidBody* f = btFractureRigidBody::upcast(body); f && f->inFractureWorld_) {
        f->inFractureWorld_ = false;
        --fractureBodies_;
    }
    // Whoever removes a world-owned fragment takes it.
    const auto it =
        std::find_if(owned_.begin(), owned_.end(), [body](const auto& b) { return b.get() == body; });
    if (it != owned_.end()) {
        it->release();
        owned_.erase(it);
    }
}

void btFractureDynamicsWorld::setSplitImpulseForFragments(bool enabled, double depth) {
    if (!(depth > 0.0) || !std::isfinite(depth))
        throw Error("btFractureDynamicsWorld: split impulse depth must be positive and finite, not " +
                    std::to_string(depth) + " m");
    splitImpulseForFragments_ = enabled;
    splitImpulseDepth_ = depth;
}

void btFractureDynamicsWorld::setFragmentSleeping(bool enabled, const FragmentSleeping& sleeping) {
    if (!(sleeping.window > 0.0) || !(sleeping.travel > 0.0) || !(sleeping.turn > 0.0) ||
        !(sleeping.minimumSpeed >= 0.0))
        throw Error(
            "btFractureDynamicsWorld: fragment sleeping window, travel and turn must be > 0 and the "
            "minimum speed >= 0");
    fragmentSleepingEnabled_ = enabled;
    fragmentSleeping_ = sleeping;
    if (enabled && !contactIslands_) {
        contactIslands_ = std::make_unique<ContactIslandManager>();
        bulletIslands_ = m_islandManager;
        m_islandManager = contactIslands_.get();
    } else if (!enabled && contactIslands_) {
        m_islandManager = bulletIslands_;
        contactIslands_.reset();
    }
}

void btFractureDynamicsWorld::updateActivationState(btScalar timeStep) {
    btDiscreteDynamicsWorld::updateActivationState(timeStep);
    if (!fragmentSleepingEnabled_) return;
    for (const auto& fragment : owned_) settleIfStill(*fragment, fragmentSleeping_);
}

void btFractureDynamicsWorld::setEnergyAuditSteps(int steps) {
    if (steps < 0)
        throw Error("btFractureDynamicsWorld: energy audit steps must be >= 0, not " + std::to_string(steps));
    energyAuditSteps_ = steps;
}

void btFractureDynamicsWorld::updateAabbs() {
    BT_PROFILE("updateAabbs");
    const bool relativeThresholds = usesRelativeThresholds(m_dispatcher1);
    for (int i = 0; i < m_collisionObjects.size(); ++i) {
        btCollisionObject* object = m_collisionObjects[i];
        if (!(m_forceUpdateAllAabbs || object->isActive())) continue;
        btFractureRigidBody* body = btFractureRigidBody::upcast(object);
        if (!body) {
            updateSingleAabb(object);
            continue;
        }
        btVector3 aabbMin, aabbMax;
        const btScalar pad = padFor(*object, relativeThresholds);
        paddedAabb(*object, getDispatchInfo().m_useContinuous, pad, aabbMin, aabbMax);
        // Bullet's guard against a runaway body (updateSingleAabb), with Bullet's pad.
        if (!object->isStaticObject() && !((aabbMax - aabbMin).length2() < btScalar(1e12))) {
            body->broadphasePad_ = gContactBreakingThreshold;
            updateSingleAabb(object);
            continue;
        }
        body->broadphasePad_ = pad;
        m_broadphasePairCache->setAabb(object->getBroadphaseHandle(), aabbMin, aabbMax, m_dispatcher1);
    }
}

void btFractureDynamicsWorld::integrateTransforms(btScalar timeStep) {
    for (const auto& fragment : owned_) {
        const double spin = limitSpinToStep(*fragment, double(timeStep));
        if (spin == 0.0) continue;
        ++stats_.spinsLimited;
        static std::atomic<bool> logged{false};
        if (!logged.exchange(true))
            logf(
                LogLevel::Info, fragment->name(), ": spin ", spin, " rad/s limited to the ",
                integrableSpin(double(timeStep)),
                " rad/s a step turns a body (pi/4 per step, Bullet's integrator); reported once per process");
    }
    SweepCandidateFilter filter(*getBroadphase()->getOverlappingPairCache(), timeStep);
    btDiscreteDynamicsWorld::integrateTransforms(timeStep);
}

void btFractureDynamicsWorld::createPredictiveContacts(btScalar timeStep) {
    SweepCandidateFilter filter(*getBroadphase()->getOverlappingPairCache(), timeStep);
    btDiscreteDynamicsWorld::createPredictiveContacts(timeStep);
}

void btFractureDynamicsWorld::internalSingleStepSimulation(btScalar timeStep) {
    const std::size_t open = audits_.size();  // audits opened in this step start following in the next
    {
        const SplitImpulseBelowDepth split(getSolverInfo(), splitImpulseForFragments_ && !owned_.empty(),
                                           splitImpulseDepth_);
        stepWithFracture(timeStep);
    }
    if (open > 0) followEnergyAudits(open);
}

void btFractureDynamicsWorld::followEnergyAudits(std::size_t count) {
    const double world = mechanicalEnergy(*this);
    count = std::min(count, audits_.size());
    bool done = false;
    for (std::size_t k = 0; k < count; ++k) {
        FractureEnergyAudit& a = audits_[k].audit;
        a.worldGain = std::max(a.worldGain, world - a.worldBefore);
        a.followingKinetic = std::max(a.followingKinetic, summedKineticEnergy(audits_[k].fragments));
        ++a.followingSteps;
        done = done || --audits_[k].stepsLeft == 0;
    }
    if (!done) return;
    // Listeners hear completed audits in event order; the rest stay open.
    std::vector<OpenAudit> still;
    for (OpenAudit& a : audits_) {
        if (a.stepsLeft == 0)
            for (FractureListener* listener : listeners_) listener->onFractureEnergyAudit(a.audit);
        else
            still.push_back(std::move(a));
    }
    audits_ = std::move(still);
}

void btFractureDynamicsWorld::finishEnergyAudits() {
    std::vector<OpenAudit> audits = std::move(audits_);
    audits_.clear();
    for (const OpenAudit& open : audits)
        for (FractureListener* listener : listeners_) listener->onFractureEnergyAudit(open.audit);
}

void btFractureDynamicsWorld::stepWithFracture(btScalar timeStep) {
    if (!enabled_ || replaying_ || fractureBodies_ == 0) {
        btDiscreteDynamicsWorld::internalSingleStepSimulation(timeStep);
        return;
    }
    if (!engine_) {
        if (!missingEngineLogged_) {
            missingEngineLogged_ = true;
            logf(LogLevel::Warning, "btFractureDynamicsWorld: no FractureEngine set; bodies will not break");
        }
        btDiscreteDynamicsWorld::internalSingleStepSimulation(timeStep);
        return;
    }
    ++stepStamp_;
    ++stats_.steps;
    snapshot_.capture(m_nonStaticRigidBodies);
    btDiscreteDynamicsWorld::internalSingleStepSimulation(timeStep);
    collectTriggeredBodies();
    if (!triggered_.empty()) runFractureEvents(timeStep);
}

void btFractureDynamicsWorld::collectTriggeredBodies() {
    touched_.clear();
    triggered_.clear();
    const int manifolds = m_dispatcher1->getNumManifolds();
    for (int m = 0; m < manifolds; ++m) {
        const btPersistentManifold* manifold = m_dispatcher1->getManifoldByIndexInternal(m);
        if (manifold->getNumContacts() == 0) continue;  // most broadphase pairs: no body touched
        btFractureRigidBody* bodies[2] = {fracturable(manifold->getBody0()),
                                          fracturable(manifold->getBody1())};
        if (!bodies[0] && !bodies[1]) continue;
        if (!wasSolved(*manifold)) continue;
        double impulse = 0.0;
        const btScalar threshold = manifold->getContactProcessingThreshold();
        for (int k = 0; k < manifold->getNumContacts(); ++k) {
            const btManifoldPoint& point = manifold->getContactPoint(k);
            if (point.getDistance() <= threshold && point.m_appliedImpulse > 0)
                impulse += double(point.m_appliedImpulse);
        }
        for (btFractureRigidBody* body : bodies) {
            if (!body) continue;
            if (body->hookStamp_ != stepStamp_) {
                body->hookStamp_ = stepStamp_;
                body->impulseSum_ = 0.0;
                touched_.push_back(body);
            }
            body->impulseSum_ += impulse;
        }
    }
    stats_.bodiesChecked += touched_.size();
    for (btFractureRigidBody* body : touched_)
        if (body->impulseSum_ >= body->settings().impulseThreshold && body->impulseSum_ > 0.0)
            triggered_.push_back(body);
    stats_.bodiesTriggered += triggered_.size();
}

bool btFractureDynamicsWorld::buildContacts(btFractureRigidBody& body,
                                            std::vector<BodyContact>& contacts) const {
    contacts.clear();
    const RigidBodySnapshot::Entry* self = snapshot_.find(&body);
    if (!self) return false;
    const Eigen::Matrix3d rotation = toEigen(self->transform.getBasis());
    const int manifolds = m_dispatcher1->getNumManifolds();
    for (int m = 0; m < manifolds; ++m) {
        const btPersistentManifold* manifold = m_dispatcher1->getManifoldByIndexInternal(m);
        const bool isBody0 = manifold->getBody0() == &body;
        if (!isBody0 && manifold->getBody1() != &body) continue;
        if (!wasSolved(*manifold)) continue;
        const btCollisionObject* other = isBody0 ? manifold->getBody1() : manifold->getBody0();
        const btRigidBody* otherRigid = btRigidBody::upcast(other);
        const btFractureRigidBody* otherFracture = btFractureRigidBody::upcast(other);
        const RigidBodySnapshot::Entry* otherState = snapshot_.find(other);
        const Material& otherMaterial = otherFracture ? otherFracture->material() : defaultMaterial_;
        const btTransform otherTransform = otherState ? otherState->transform : other->getWorldTransform();
        const btScalar threshold = manifold->getContactProcessingThreshold();
        for (int k = 0; k < manifold->getNumContacts(); ++k) {
            const btManifoldPoint& point = manifold->getContactPoint(k);
            if (point.getDistance() > threshold || !(point.m_appliedImpulse > 0)) continue;
            // Bullet's normal points from body1 to body0: the impulse on body0 is +J n.
            const Eigen::Vector3d normalOnB = toEigen(point.m_normalWorldOnB);
            const Eigen::Vector3d worldDirection = isBody0 ? normalOnB : Eigen::Vector3d(-normalOnB);
            const Eigen::Vector3d selfLocal = toEigen(isBody0 ? point.m_localPointA : point.m_localPointB);
            const Eigen::Vector3d otherLocal = toEigen(isBody0 ? point.m_localPointB : point.m_localPointA);

            // Approach speed from the pre-step velocities: the relative velocity of the other body's
            // point towards this one's, along the direction of the impulse on this body.
            const Eigen::Vector3d selfPoint = toEigen(self->transform * toBullet(selfLocal));
            const Eigen::Vector3d otherPoint = toEigen(otherTransform * toBullet(otherLocal));
            const Eigen::Vector3d selfVelocity =
                toEigen(self->linearVelocity) +
                toEigen(self->angularVelocity).cross(selfPoint - toEigen(self->transform.getOrigin()));
            Eigen::Vector3d otherVelocity = Eigen::Vector3d::Zero();
            if (otherState)
                otherVelocity = toEigen(otherState->linearVelocity) +
                                toEigen(otherState->angularVelocity)
                                    .cross(otherPoint - toEigen(otherState->transform.getOrigin()));
            else if (otherRigid)
                otherVelocity = toEigen(
                    otherRigid->getVelocityInLocalPoint(toBullet(otherPoint) - otherTransform.getOrigin()));
            const double approach = std::max(0.0, (otherVelocity - selfVelocity).dot(worldDirection));

            HertzBody a{body.material().youngsModulus(), body.material().poissonRatio(),
                        double(body.getInvMass()), engine_->meanCurvature(body, selfLocal)};
            HertzBody b{otherMaterial.youngsModulus(), otherMaterial.poissonRatio(),
                        otherRigid ? double(otherRigid->getInvMass()) : 0.0,
                        otherFracture ? engine_->meanCurvature(*otherFracture, otherLocal)
                                      : shapeMeanCurvature(*other->getCollisionShape(), otherLocal)};
            if (a.inverseMass + b.inverseMass <= 0.0) continue;  // static against static: no impact
            const HertzImpact hertz = hertzImpact(a, b, approach, body.characteristicLength());

            BodyContact contact;
            contact.point = selfLocal;
            contact.direction = rotation.transpose() * worldDirection;
            contact.impulse = double(point.m_appliedImpulse);
            contact.approachSpeed = approach;
            contact.duration = hertz.contactDuration;
            contact.peakForce = hertz.peakForce;
            contact.effectiveModulus = hertz.effectiveModulus;
            contact.effectiveRadius = hertz.effectiveRadius;
            contact.effectiveMass = hertz.effectiveMass;
            contacts.push_back(contact);
        }
    }
    return !contacts.empty();
}

void btFractureDynamicsWorld::runFractureEvents(btScalar timeStep) {
    std::vector<Event> events;
    std::vector<BodyContact> contacts;
    for (btFractureRigidBody* body : triggered_) {
        if (body->getNumConstraintRefs() > 0) {
            logf(LogLevel::Warning, body->name(), ": has ", body->getNumConstraintRefs(),
                 " constraints, which btFracture cannot move to fragments; the body is made unbreakable");
            FractureBodySettings settings = body->settings();
            settings.fracturable = false;
            body->setSettings(settings);
            continue;
        }
        Event event{body, {}, {}, {}, {}, {}, {}, 0.0};
        Timer timer;
        try {
            const bool touching = buildContacts(*body, contacts);
            stats_.contactSeconds += timer.seconds();
            if (!touching) continue;
            event.info.step = stats_.steps;
            event.info.contacts = static_cast<int>(contacts.size());
            event.info.impulseSum = body->impulseSum_;
            for (const BodyContact& c : contacts)
                event.info.contactDuration = std::max(event.info.contactDuration, c.duration);
            ++stats_.engineCalls;
            timer.restart();
            event.outcome = engine_->fracture(*body, contacts, stats_);
            event.info.engineSeconds = timer.seconds();
            stats_.engineSeconds += event.info.engineSeconds;
            event.info.engineTimings = event.outcome.timings;
            event.info.crackTriangles = event.outcome.crackTriangles;
            stats_.maxLoadRatio = std::max(stats_.maxLoadRatio, event.outcome.maxLoadRatio);
            for (std::size_t k = 0; k < event.outcome.fragments.size(); ++k)
                validateSpec(event.outcome.fragments[k], body->originalVolume(),
                             body->name() + ": fragment " + std::to_string(k));
        } catch (const Error& error) {
            if (event.info.engineSeconds == 0.0) stats_.engineSeconds += timer.seconds();  // fracture() threw
            ++stats_.engineFailures;
            logf(LogLevel::Error, body->name(), ": fracture failed, body made unbreakable: ", error.what());
            FractureBodySettings settings = body->settings();
            settings.fracturable = false;
            body->setSettings(settings);
            continue;
        }
        if (event.outcome.fragments.empty()) continue;
        event.staticContacts = staticContactsOf(*m_dispatcher1, *body);
        event.partners = dynamicContactPartners(*m_dispatcher1, *body);
        events.push_back(std::move(event));
    }
    if (events.empty()) return;

    Timer swapTimer;
    snapshot_.restore();
    const double worldBefore = mechanicalEnergy(*this);
    for (Event& event : events) {
        event.energy.event = event.info.event = stats_.fractureEvents;
        event.energy.worldBefore = worldBefore;
        event.energy.bodyKinetic = kineticEnergy(*event.parent);
        event.energy.partnersKinetic = summedKineticEnergy(event.partners);
        event.fragments = spawnFragments(*event.parent, event.outcome);
        event.energy.swapKinetic = rigidMotionKineticEnergy(event.fragments, *event.parent);
        event.bodyPotential = potentialEnergy(*event.parent);
        event.energy.swapPotentialGain =
            potentialEnergy(event.fragments, event.parent->getGravity()) - event.bodyPotential;
        ++stats_.fractureEvents;
        stats_.fragmentsSpawned += event.fragments.size();
    }

    // Cut overlapping convex pieces of the new fragments apart, push what still overlaps apart,
    // then give the fragments the parent's rigid motion (momentum-exact).
    std::vector<btFractureRigidBody*> spawned;
    std::vector<SeparationBody> separation;
    std::vector<char> reshaped;
    for (const Event& event : events) {
        std::vector<ConvexPolytope> parentPieces = event.parent->shapeStorage().convexPieces();
        for (ConvexPolytope& piece : parentPieces)
            for (auto& p : piece.points) p = toEigen(event.parent->getWorldTransform() * toBullet(p));
        for (btFractureRigidBody* f : event.fragments) {
            spawned.push_back(f);
            SeparationBody s;
            s.mass = 1.0 / double(f->getInvMass());
            s.length = f->characteristicLength();
            for (const ConvexPolytope& piece : f->shapeStorage().convexPieces()) {
                ConvexPolytope world = piece;
                for (auto& p : world.points) p = toEigen(f->getWorldTransform() * toBullet(p));
                s.pieces.push_back(std::move(world));
            }
            s.blockedDirections = blockedNormals(event.staticContacts, s.pieces, s.length);
            reshaped.push_back(!parentPieces.empty() && containWithin(s, parentPieces));
            separation.push_back(std::move(s));
        }
    }
    const TrimResult trim = trimOverlaps(separation);
    for (std::size_t k = 0; k < spawned.size(); ++k) {
        if (!trim.changed[k] && !reshaped[k]) continue;
        const btTransform toBody = spawned[k]->getWorldTransform().inverse();
        std::vector<ConvexPolytope> pieces = separation[k].pieces;
        for (ConvexPolytope& piece : pieces)
            for (auto& p : piece.points) p = toEigen(toBody * toBullet(p));
        spawned[k]->replaceConvexPieces(std::move(pieces));
    }
    if (trim.cuts > 0)
        logf(LogLevel::Debug, "fragment separation: ", trim.cuts, " overlapping convex pieces cut apart, ",
             trim.declined, " left to the push");
    const SeparationResult pushes = separateOverlaps(separation);
    std::size_t index = 0;
    for (Event& event : events) {
        const std::vector<Eigen::Vector3d> eventPushes(
            pushes.pushes.begin() + static_cast<std::ptrdiff_t>(index),
            pushes.pushes.begin() + static_cast<std::ptrdiff_t>(index + event.fragments.size()));
        index += event.fragments.size();
        assignParentMotion(event.fragments, eventPushes, *event.parent);
        event.info.maxSeparationPush = pushes.largestPush;
        for (const btFractureRigidBody* f : event.fragments)
            event.energy.separatedKinetic += kineticEnergy(*f);
        event.energy.separatedPotentialGain =
            potentialEnergy(event.fragments, event.parent->getGravity()) - event.bodyPotential;
    }

    // Swap: parents out (their manifolds go with their broadphase pairs), fragments in, with
    // gravity for the rest of this stepSimulation call. World-owned parents are kept until the
    // listeners have seen them.
    std::vector<std::unique_ptr<btFractureRigidBody>> retired;
    for (Event& event : events) {
        btFractureRigidBody* parent = event.parent;
        const btBroadphaseProxy* proxy = parent->getBroadphaseHandle();
        const int group = proxy ? proxy->m_collisionFilterGroup : int(btBroadphaseProxy::DefaultFilter);
        const int mask = proxy ? proxy->m_collisionFilterMask : int(btBroadphaseProxy::AllFilter);
        const auto owned =
            std::find_if(owned_.begin(), owned_.end(), [parent](const auto& b) { return b.get() == parent; });
        if (owned != owned_.end()) {
            retired.push_back(std::move(*owned));
            owned_.erase(owned);
        }
        removeRigidBody(parent);
        // The parent has left the world for good: its fracture state (BEM, crack system, level
        // set; hundreds of MB for a large body) goes now, not when the application deletes it.
        parent->releaseFractureState();
        for (btFractureRigidBody* f : event.fragments) {
            addRigidBody(f, group, mask);
            f->applyGravity();
        }
    }
    const double swapSeconds = swapTimer.seconds();
    stats_.swapSeconds += swapSeconds;
    for (Event& event : events) event.info.swapSeconds = swapSeconds;
    for (Event& event : events)
        for (FractureListener* listener : listeners_)
            listener->onFractureEvent(*event.parent, event.fragments, event.info);
    retired.clear();

    replaying_ = true;
    {
        auto* dispatcher = dynamic_cast<btCollisionDispatcher*>(m_dispatcher1);
        std::optional<NewPairMultipoint> multipoint;
        if (dispatcher && collisionConfiguration_) multipoint.emplace(*dispatcher, *collisionConfiguration_);
        const SplitImpulseBelowDepth split(getSolverInfo(), splitImpulseForFragments_, splitImpulseDepth_);
        btDiscreteDynamicsWorld::internalSingleStepSimulation(timeStep);
    }
    if (separatedPairs_) separatedPairs_->install();  // NewPairMultipoint put back the configuration's
    replaying_ = false;
    ++stats_.replayedSteps;

    const double worldAfter = mechanicalEnergy(*this);
    for (Event& event : events) {
        OpenAudit open;
        open.audit = event.energy;
        // Fragments that broke again in this step's listeners are gone; the rest are followed.
        for (const btFractureRigidBody* f : event.fragments)
            if (f->isInWorld()) open.fragments.push_back(f);
        open.audit.replayKinetic = summedKineticEnergy(open.fragments);
        open.audit.followingKinetic = open.audit.replayKinetic;
        open.audit.worldGain = worldAfter - open.audit.worldBefore;
        open.stepsLeft = energyAuditSteps_;
        if (open.stepsLeft == 0)
            for (FractureListener* listener : listeners_) listener->onFractureEnergyAudit(open.audit);
        else
            audits_.push_back(std::move(open));
    }
}

std::vector<btFractureRigidBody*> btFractureDynamicsWorld::spawnFragments(btFractureRigidBody& parent,
                                                                          FractureOutcome& outcome) {
    std::vector<btFractureRigidBody*> fragments;
    const btTransform parentTransform = parent.getWorldTransform();
    const FractureBodySettings& parentSettings = parent.settings();
    bool parentStateTaken = false;
    for (std::size_t k = 0; k < outcome.fragments.size(); ++k) {
        FragmentSpec& spec = outcome.fragments[k];
        const PrincipalAxes axes = principalAxes(spec.inertiaAboutCom);
        TriangleMesh mesh = std::move(spec.collisionMesh);
        mesh.name = parent.rootName() + "_f" + std::to_string(++fragmentsOf_[parent.rootName()]);
        for (auto& v : mesh.vertices) v = axes.rotation.transpose() * (v - spec.centreOfMass);

        const bool breaks =
            spec.cls == FragmentSpec::Class::Breakable || spec.cls == FragmentSpec::Class::KeepsParentSolver;
        FractureBodySettings settings = parentSettings;
        // A new generation, except the > 95 % piece, which continues its parent (§5.2 (d)).
        if (spec.cls != FragmentSpec::Class::KeepsParentSolver)
            settings.refractureDepth = parentSettings.refractureDepth + 1;
        settings.fracturable = breaks && parentSettings.fracturable;

        const CollisionShapeKind kind = spec.cls == FragmentSpec::Class::ConvexHull
                                            ? CollisionShapeKind::ConvexHull
                                            : collisionShapeKind(settings, mesh);
        auto shape = buildCollisionShape(mesh, kind, parentSettings.shapeOptions);
        const btTransform local = toBullet(axes.rotation, spec.centreOfMass);
        auto body = std::make_unique<btFractureRigidBody>(
            parent.material(), std::move(mesh), std::move(shape), spec.volume, axes.moments,
            parent.originalVolume(), settings, parentTransform * local);
        body->rootName_ = parent.rootName();
        if (spec.cls == FragmentSpec::Class::KeepsParentSolver) {
            if (!parentStateTaken)
                body->setFractureState(parent.releaseFractureState());
            else
                logf(LogLevel::Warning, parent.name(),
                     ": more than one fragment claims to keep the parent's solver; ", body->name(),
                     " starts without state");
            parentStateTaken = true;
        } else if (spec.cls == FragmentSpec::Class::Breakable) {
            body->setFractureState(std::move(spec.carriedState));
        }
        // Surface and damping properties, filters and identity come from the parent.
        body->setFriction(parent.getFriction());
        body->setRollingFriction(parent.getRollingFriction());
        body->setSpinningFriction(parent.getSpinningFriction());
        body->setRestitution(parent.getRestitution());
        body->setDamping(parent.getLinearDamping(), parent.getAngularDamping());
        if (fragmentSleepingEnabled_)
            setFragmentSleepingThresholds(*body, body->characteristicLength(), fragmentSleeping_);
        else
            body->setSleepingThresholds(parent.getLinearSleepingThreshold(),
                                        parent.getAngularSleepingThreshold());
        body->setFlags(parent.getFlags());
        body->setCollisionFlags(parent.getCollisionFlags());
        body->setUserPointer(parent.getUserPointer());
        body->setUserIndex(parent.getUserIndex());
        if (parent.getFlags() & BT_DISABLE_WORLD_GRAVITY) body->setGravity(parent.getGravity());
        if (parent.getCcdMotionThreshold() > 0) {
            const btScalar scale = btScalar(body->characteristicLength() / parent.characteristicLength());
            body->setCcdMotionThreshold(parent.getCcdMotionThreshold() * scale);
            body->setCcdSweptSphereRadius(parent.getCcdSweptSphereRadius() * scale);
        } else {
            // Chips are small and start at their parent's speed: one that moves more than half its
            // size in a step is swept (continuous collision), so it cannot pass through the ground.
            const double size = body->characteristicLength();
            body->setCcdMotionThreshold(btScalar(0.5 * size));
            body->setCcdSweptSphereRadius(btScalar(0.2 * size));
        }
        body->setActivationState(ACTIVE_TAG);
        fragments.push_back(body.get());
        owned_.push_back(std::move(body));
    }
    return fragments;
}

}  // namespace btfracture
