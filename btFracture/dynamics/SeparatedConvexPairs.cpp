// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/SeparatedConvexPairs.h>

#include <btFracture/dynamics/SeparatedPairCache.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <memory>
#include <vector>

namespace btfracture {
namespace {

// Bullet's algorithm on its own manifold, called only when the cache cannot rule out a contact.
class SkippingAlgorithm : public btCollisionAlgorithm {
public:
    SkippingAlgorithm(btCollisionAlgorithmConstructionInfo& ci, btCollisionAlgorithm* inner)
        : btCollisionAlgorithm(ci), inner_(inner) {}
    ~SkippingAlgorithm() override {
        inner_->~btCollisionAlgorithm();
        m_dispatcher->freeCollisionAlgorithm(inner_);
    }
    void processCollision(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b,
                          const btDispatcherInfo& info, btManifoldResult* result) override {
        // The first call runs: it makes the manifold, in the dispatcher's order.
        btPersistentManifold* m = manifold();
        if (m && cache_->apart(*a, *b, *m)) return;
        inner_->processCollision(a, b, info, result);
    }
    btScalar calculateTimeOfImpact(btCollisionObject* a, btCollisionObject* b, const btDispatcherInfo& info,
                                   btManifoldResult* result) override {
        return inner_->calculateTimeOfImpact(a, b, info, result);
    }
    void getAllContactManifolds(btManifoldArray& manifolds) override {
        inner_->getAllContactManifolds(manifolds);
    }

private:
    // The inner algorithm's manifold, made on its first call and kept for its life.
    btPersistentManifold* manifold() {
        if (!manifold_) {
            btManifoldArray manifolds;
            inner_->getAllContactManifolds(manifolds);
            if (manifolds.size() == 1) manifold_ = manifolds[0];
        }
        return manifold_;
    }
    btCollisionAlgorithm* inner_;
    btPersistentManifold* manifold_ = nullptr;
    // Kept out of the dispatcher's pool, whose elements are sized for Bullet's algorithms.
    std::unique_ptr<SeparatedPairCache> cache_ = std::make_unique<SeparatedPairCache>();
};

class SkippingCreateFunc : public btCollisionAlgorithmCreateFunc {
public:
    explicit SkippingCreateFunc(btCollisionAlgorithmCreateFunc& inner) : inner_(inner) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override {
        btCollisionAlgorithm* inner = inner_.CreateCollisionAlgorithm(ci, a, b);
        if (ci.m_manifold != nullptr) return inner;  // a compound child: the parent refreshes
        void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SkippingAlgorithm));
        return new (memory) SkippingAlgorithm(ci, inner);
    }

private:
    btCollisionAlgorithmCreateFunc& inner_;
};

}  // namespace

struct SeparatedConvexPairs::Registered {
    std::unique_ptr<SkippingCreateFunc> func;
    btCollisionAlgorithmCreateFunc* original = nullptr;
    std::vector<std::pair<int, int>> types;
};

SeparatedConvexPairs::SeparatedConvexPairs(btCollisionDispatcher& dispatcher,
                                           btCollisionConfiguration& configuration)
    : dispatcher_(dispatcher), registered_(std::make_unique<Registered>()) {
    btCollisionAlgorithmCreateFunc* original = configuration.getCollisionAlgorithmCreateFunc(
        CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE);
    // Perturbed contacts may land within the threshold of a pair whose gap exceeds it.
    auto* convex = dynamic_cast<btConvexConvexAlgorithm::CreateFunc*>(original);
    if (!convex || convex->m_numPerturbationIterations != 0) return;
    registered_->func = std::make_unique<SkippingCreateFunc>(*original);
    registered_->original = original;
    for (int type0 = 0; type0 < MAX_BROADPHASE_COLLISION_TYPES; ++type0)
        for (int type1 = 0; type1 < MAX_BROADPHASE_COLLISION_TYPES; ++type1)
            if (configuration.getCollisionAlgorithmCreateFunc(type0, type1) == original)
                registered_->types.emplace_back(type0, type1);
    install();
}

SeparatedConvexPairs::~SeparatedConvexPairs() {
    for (const auto& [type0, type1] : registered_->types)
        dispatcher_.registerCollisionCreateFunc(type0, type1, registered_->original);
}

void SeparatedConvexPairs::install() {
    for (const auto& [type0, type1] : registered_->types)
        dispatcher_.registerCollisionCreateFunc(type0, type1, registered_->func.get());
}

}  // namespace btfracture
