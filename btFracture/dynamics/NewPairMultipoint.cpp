// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/NewPairMultipoint.h>

#include <btFracture/dynamics/SeparatedPairCache.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <memory>
#include <vector>

namespace btfracture {
namespace {

struct Perturbation {
    int iterations = 0, minimumPoints = 0;
};

// Makes one of Bullet's convex algorithms on a given manifold with given perturbation settings.
class PhasedCreateFunc : public btCollisionAlgorithmCreateFunc {
public:
    // `separable`: the algorithm may be skipped while the pair is apart (SeparatedPairCache).
    PhasedCreateFunc(Perturbation plain, bool separable) : plain_(plain), separable_(separable) {}
    virtual btCollisionAlgorithm* make(btCollisionAlgorithmConstructionInfo& ci,
                                       const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b,
                                       btPersistentManifold* manifold, Perturbation perturbation) = 0;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override;
    Perturbation plain() const { return plain_; }
    bool separable() const { return separable_; }

private:
    Perturbation plain_;
    bool separable_;
};

// Runs the perturbed algorithm for the first kPerturbedSteps calls, then the plain one (between
// two moving bodies), both on one manifold (its own, unless a compound parent shares one). A
// convex pair on its own manifold skips the calls that cannot find a contact.
class PhasedAlgorithm : public btCollisionAlgorithm {
public:
    PhasedAlgorithm(btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                    const btCollisionObjectWrapper* b, PhasedCreateFunc& func)
        : btCollisionAlgorithm(ci),
          ownManifold_(ci.m_manifold == nullptr),
          plainIterations_(func.plain().iterations) {
        // Kept out of the dispatcher's pool, whose elements are sized for Bullet's algorithms.
        if (func.separable() && ownManifold_) cache_ = std::make_unique<SeparatedPairCache>();
        // The manifold's body order is the algorithm's own (convex first for a plane pair), from
        // which btManifoldResult orients the normals.
        const btCollisionObject* first = (func.m_swapped ? b : a)->getCollisionObject();
        const btCollisionObject* second = (func.m_swapped ? a : b)->getCollisionObject();
        manifold_ = ownManifold_ ? m_dispatcher->getNewManifold(first, second) : ci.m_manifold;
        perturbed_ = func.make(ci, a, b, manifold_,
                               {NewPairMultipoint::kIterations, NewPairMultipoint::kMinimumPoints});
        // Against static or kinematic geometry (the ground) a piece keeps perturbing for life: a
        // chip resting there on one point per step can sink through it.
        const bool onStatic = a->getCollisionObject()->isStaticOrKinematicObject() ||
                              b->getCollisionObject()->isStaticOrKinematicObject();
        plain_ = onStatic ? nullptr : func.make(ci, a, b, manifold_, func.plain());
    }
    ~PhasedAlgorithm() override {
        for (btCollisionAlgorithm* algorithm : {perturbed_, plain_}) {
            if (!algorithm) continue;
            algorithm->~btCollisionAlgorithm();
            m_dispatcher->freeCollisionAlgorithm(algorithm);
        }
        if (ownManifold_) m_dispatcher->releaseManifold(manifold_);
    }
    void processCollision(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b,
                          const btDispatcherInfo& info, btManifoldResult* result) override {
        const bool plain = plain_ && steps_ >= NewPairMultipoint::kPerturbedSteps;
        if (steps_ < NewPairMultipoint::kPerturbedSteps) ++steps_;
        // A perturbed query turns one body so that none of its points moves more than
        // gContactBreakingThreshold (btConvexConvexAlgorithm's perturbation angle); its GJK reports
        // points up to both margins beyond the threshold, and mapped back to the unturned body such
        // a point may land within the threshold.
        const int iterations = plain ? plainIterations_ : NewPairMultipoint::kIterations;
        const btScalar reach = iterations == 0
                                   ? btScalar(0)
                                   : gContactBreakingThreshold + a->getCollisionShape()->getMargin() +
                                         b->getCollisionShape()->getMargin();
        if (cache_ && cache_->apart(*a, *b, *manifold_, reach)) return;
        (plain ? plain_ : perturbed_)->processCollision(a, b, info, result);
        // Bullet's algorithms leave refreshing a manifold they do not own to its owner.
        if (ownManifold_ && manifold_->getNumContacts() > 0) {
            result->setPersistentManifold(manifold_);
            result->refreshContactPoints();
        }
    }
    btScalar calculateTimeOfImpact(btCollisionObject* a, btCollisionObject* b, const btDispatcherInfo& info,
                                   btManifoldResult* result) override {
        return perturbed_->calculateTimeOfImpact(a, b, info, result);
    }
    void getAllContactManifolds(btManifoldArray& manifolds) override {
        if (ownManifold_) manifolds.push_back(manifold_);
    }

private:
    bool ownManifold_;
    int plainIterations_;
    btPersistentManifold* manifold_ = nullptr;
    btCollisionAlgorithm* perturbed_ = nullptr;
    btCollisionAlgorithm* plain_ = nullptr;
    int steps_ = 0;
    std::unique_ptr<SeparatedPairCache> cache_;
};

btCollisionAlgorithm* PhasedCreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                                 const btCollisionObjectWrapper* a,
                                                                 const btCollisionObjectWrapper* b) {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(PhasedAlgorithm));
    return new (memory) PhasedAlgorithm(ci, a, b, *this);
}

class PhasedConvexConvex : public PhasedCreateFunc {
public:
    explicit PhasedConvexConvex(const btConvexConvexAlgorithm::CreateFunc& original)
        : PhasedCreateFunc(
              {original.m_numPerturbationIterations, original.m_minimumPointsPerturbationThreshold},
              /*separable=*/true),
          solver_(original.m_pdSolver) {}
    btCollisionAlgorithm* make(btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                               const btCollisionObjectWrapper* b, btPersistentManifold* manifold,
                               Perturbation p) override {
        void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(btConvexConvexAlgorithm));
        return new (memory)
            btConvexConvexAlgorithm(manifold, ci, a, b, solver_, p.iterations, p.minimumPoints);
    }

private:
    btConvexPenetrationDepthSolver* solver_;
};

class PhasedConvexPlane : public PhasedCreateFunc {
public:
    explicit PhasedConvexPlane(const btConvexPlaneCollisionAlgorithm::CreateFunc& original)
        : PhasedCreateFunc(
              {original.m_numPerturbationIterations, original.m_minimumPointsPerturbationThreshold},
              /*separable=*/false) {
        m_swapped = original.m_swapped;
    }
    btCollisionAlgorithm* make(btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                               const btCollisionObjectWrapper* b, btPersistentManifold* manifold,
                               Perturbation p) override {
        void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(btConvexPlaneCollisionAlgorithm));
        return new (memory)
            btConvexPlaneCollisionAlgorithm(manifold, ci, a, b, m_swapped, p.iterations, p.minimumPoints);
    }
};

}  // namespace

struct NewPairMultipoint::Registered {
    std::vector<std::unique_ptr<PhasedCreateFunc>> funcs;
    struct Entry {
        int type0, type1;
        btCollisionAlgorithmCreateFunc* original;
    };
    std::vector<Entry> entries;
};

NewPairMultipoint::NewPairMultipoint(btCollisionDispatcher& dispatcher,
                                     btCollisionConfiguration& configuration)
    : dispatcher_(dispatcher), registered_(std::make_unique<Registered>()) {
    // The create functions of convex hull against convex hull and against a plane (both orders);
    // Bullet's default configuration shares them with the other convex shape pairs (boxes too).
    const int hull = CONVEX_HULL_SHAPE_PROXYTYPE, plane = STATIC_PLANE_PROXYTYPE;
    std::vector<std::pair<btCollisionAlgorithmCreateFunc*, PhasedCreateFunc*>> phased;
    for (const auto& [type0, type1] :
         {std::pair{hull, hull}, std::pair{hull, plane}, std::pair{plane, hull}}) {
        btCollisionAlgorithmCreateFunc* original =
            configuration.getCollisionAlgorithmCreateFunc(type0, type1);
        std::unique_ptr<PhasedCreateFunc> func;
        if (auto* convex = dynamic_cast<btConvexConvexAlgorithm::CreateFunc*>(original))
            func = std::make_unique<PhasedConvexConvex>(*convex);
        else if (auto* convexPlane = dynamic_cast<btConvexPlaneCollisionAlgorithm::CreateFunc*>(original))
            func = std::make_unique<PhasedConvexPlane>(*convexPlane);
        if (!func) continue;
        phased.emplace_back(original, func.get());
        registered_->funcs.push_back(std::move(func));
    }
    for (int type0 = 0; type0 < MAX_BROADPHASE_COLLISION_TYPES; ++type0)
        for (int type1 = 0; type1 < MAX_BROADPHASE_COLLISION_TYPES; ++type1) {
            btCollisionAlgorithmCreateFunc* original =
                configuration.getCollisionAlgorithmCreateFunc(type0, type1);
            for (const auto& [from, to] : phased)
                if (original == from) {
                    dispatcher.registerCollisionCreateFunc(type0, type1, to);
                    registered_->entries.push_back({type0, type1, original});
                    break;
                }
        }
}

NewPairMultipoint::~NewPairMultipoint() {
    for (const Registered::Entry& e : registered_->entries)
        dispatcher_.registerCollisionCreateFunc(e.type0, e.type1, e.original);
}

}  // namespace btfracture
