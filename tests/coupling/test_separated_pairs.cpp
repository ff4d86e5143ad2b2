// SPDX-License-Identifier: Zlib
// SeparatedConvexPairs and SeparatedPairCache: a convex pair that is apart skips Bullet's
// convex-convex algorithm while its gap bound exceeds the contact breaking threshold, and a pair
// that approaches at speed gets bit-identical contacts on the same pass as without the cache.
#include <btFracture/dynamics/NewPairMultipoint.h>
#include <btFracture/dynamics/SeparatedConvexPairs.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

using namespace btfracture;

namespace {

// Bullet's convex-convex algorithm, counting its calls.
struct CountingCreateFunc : btConvexConvexAlgorithm::CreateFunc {
    struct Algorithm : btConvexConvexAlgorithm {
        Algorithm(btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
                  const btCollisionObjectWrapper* b, CountingCreateFunc& func)
            : btConvexConvexAlgorithm(ci.m_manifold, ci, a, b, func.m_pdSolver, 0, 3), calls(func.calls) {}
        void processCollision(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b,
                              const btDispatcherInfo& info, btManifoldResult* result) override {
            ++calls;
            btConvexConvexAlgorithm::processCollision(a, b, info, result);
        }
        int& calls;
    };
    explicit CountingCreateFunc(btConvexPenetrationDepthSolver* solver) : CreateFunc(solver) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override {
        void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(Algorithm));
        return new (memory) Algorithm(ci, a, b, *this);
    }
    int calls = 0;
};

// Bullet's default configuration with the counting algorithm for convex hull pairs.
struct CountingConfiguration : btDefaultCollisionConfiguration {
    btGjkEpaPenetrationDepthSolver solver;
    CountingCreateFunc counting{&solver};
    btCollisionAlgorithmCreateFunc* getCollisionAlgorithmCreateFunc(int type0, int type1) override {
        btCollisionAlgorithmCreateFunc* own =
            btDefaultCollisionConfiguration::getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE,
                                                                             CONVEX_HULL_SHAPE_PROXYTYPE);
        btCollisionAlgorithmCreateFunc* func =
            btDefaultCollisionConfiguration::getCollisionAlgorithmCreateFunc(type0, type1);
        return func == own ? &counting : func;
    }
};

// Two boxes (convex hulls, 0.2 m cubes by default) turned by `angle` about z, face to face along
// the face normal (cos angle, sin angle, 0), their faces `gap` apart, the second shifted by
// `offset` along the face (along (-sin angle, cos angle, 0)). At 45 degrees (the default) their
// bounding boxes overlap while the faces are up to 8 cm apart; at 0 the boxes fit the cubes.
struct FacingCubes {
    CountingConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btCollisionWorld world{&dispatcher, &broadphase, &config};
    btConvexHullShape shape;
    btCollisionObject a, b;
    std::optional<SeparatedConvexPairs> separated;
    const btQuaternion turned;
    const btVector3 normal;

    FacingCubes(bool withCache, float gap, float angle = SIMD_PI * 0.25f,
                const btVector3& halfExtents = btVector3(0.1f, 0.1f, 0.1f), float offset = 0.0f)
        : turned(btVector3(0, 0, 1), angle), normal(std::cos(angle), std::sin(angle), 0.0f) {
        for (int k = 0; k < 8; ++k)
            shape.addPoint(btVector3(k & 1 ? halfExtents.x() : -halfExtents.x(),
                                     k & 2 ? halfExtents.y() : -halfExtents.y(),
                                     k & 4 ? halfExtents.z() : -halfExtents.z()));
        shape.setMargin(0.0f);
        shape.recalcLocalAabb();  // the box cached by addPoint holds Bullet's default margin
        if (withCache) separated.emplace(dispatcher, config);
        place(a, btVector3(0, 0, 0));
        const btVector3 side(-normal.y(), normal.x(), 0.0f);
        place(b, normal * (2.0f * halfExtents.x() + gap) + side * offset);
    }
    ~FacingCubes() {
        world.removeCollisionObject(&b);
        world.removeCollisionObject(&a);
    }
    void place(btCollisionObject& object, const btVector3& origin) {
        object.setCollisionShape(&shape);
        object.setWorldTransform(btTransform(turned, origin));
        world.addCollisionObject(&object);
    }
    // Moves b by `step` along the face normal and turns it by `turn` about z.
    void move(float step, float turn) {
        btTransform t = b.getWorldTransform();
        t.setOrigin(t.getOrigin() + normal * step);
        t.setRotation(btQuaternion(btVector3(0, 0, 1), turn) * t.getRotation());
        b.setWorldTransform(t);
    }
    std::vector<btManifoldPoint> pass() {
        world.performDiscreteCollisionDetection();
        std::vector<btManifoldPoint> points;
        for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
            const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
            for (int p = 0; p < manifold->getNumContacts(); ++p)
                points.push_back(manifold->getContactPoint(p));
        }
        return points;
    }
    int pairs() { return broadphase.getOverlappingPairCache()->getNumOverlappingPairs(); }
};

void expectSamePoints(const std::vector<btManifoldPoint>& got, const std::vector<btManifoldPoint>& want,
                      int pass) {
    ASSERT_EQ(got.size(), want.size()) << "pass " << pass;
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(got[i].m_positionWorldOnA[k], want[i].m_positionWorldOnA[k]) << "pass " << pass;
            EXPECT_EQ(got[i].m_positionWorldOnB[k], want[i].m_positionWorldOnB[k]) << "pass " << pass;
            EXPECT_EQ(got[i].m_normalWorldOnB[k], want[i].m_normalWorldOnB[k]) << "pass " << pass;
            EXPECT_EQ(got[i].m_distance1, want[i].m_distance1) << "pass " << pass;
        }
}

}  // namespace

// 83 mm apart (threshold: 2 % of the cube's bounding radius, 3.5 mm) and moving apart by 1 mm a
// pass: Bullet's algorithm runs once, on the pass that measures the gap; without the cache it
// runs on every pass.
TEST(SeparatedConvexPairs, PairMovingApartIsSkipped) {
    const float gap = 0.083f;
    for (bool withCache : {false, true}) {
        FacingCubes cubes(withCache, gap);
        const int passes = 20;
        for (int pass = 0; pass < passes; ++pass) {
            EXPECT_TRUE(cubes.pass().empty());
            cubes.move(0.001f, 0.0f);
        }
        ASSERT_EQ(cubes.pairs(), 1) << "the bounding boxes must overlap for the test to mean anything";
        EXPECT_EQ(cubes.config.counting.calls, withCache ? 1 : passes) << "with cache " << withCache;
    }
}

// Approaching at 10 mm a pass while turning 0.02 rad a pass, and turning in place at 0.06 rad a
// pass until a corner reaches the other cube: the contact appears on the same pass, with the same
// points bit for bit, as without the cache; the cache skipped passes before it.
TEST(SeparatedConvexPairs, ApproachingPairGetsItsContactOnTheSamePass) {
    struct Motion {
        float gap, step, turn;
    };
    for (const Motion& motion : {Motion{0.083f, -0.01f, 0.02f}, Motion{0.03f, 0.0f, 0.06f}}) {
        FacingCubes plain(false, motion.gap), cached(true, motion.gap);
        int firstContact = -1;
        for (int pass = 0; pass < 16; ++pass) {
            const std::vector<btManifoldPoint> want = plain.pass();
            expectSamePoints(cached.pass(), want, pass);
            if (firstContact < 0 && !want.empty()) firstContact = pass;
            plain.move(motion.step, motion.turn);
            cached.move(motion.step, motion.turn);
        }
        EXPECT_GE(firstContact, 5) << "the pair must start apart for several passes (turn " << motion.turn
                                   << ")";
        EXPECT_LT(cached.config.counting.calls, plain.config.counting.calls);
    }
}

// Two 1 m long, 2 cm thick plates face to face 3 cm apart, shifted by 0.9 m along their length:
// the line between their centres runs almost along the plates (the gap along it is negative) and
// their turned bounding boxes overlap, so only GJK's axis, the faces' normal, shows the pair
// apart. Approaching at 2 mm a pass: the contact on the same pass, with the same points bit for
// bit, as without the cache, and Bullet's algorithm skipped on the passes before it.
TEST(SeparatedConvexPairs, OffsetPlatesSkippedAlongGjksAxisUntilTheirContact) {
    const btVector3 plate(0.01f, 0.5f, 0.1f);
    FacingCubes plain(false, 0.03f, SIMD_PI * 0.25f, plate, 0.9f);
    FacingCubes cached(true, 0.03f, SIMD_PI * 0.25f, plate, 0.9f);
    int firstContact = -1;
    for (int pass = 0; pass < 20; ++pass) {
        const std::vector<btManifoldPoint> want = plain.pass();
        expectSamePoints(cached.pass(), want, pass);
        if (pass == 0) {
            ASSERT_EQ(cached.pairs(), 1) << "the broadphase leaves must overlap";
        }
        if (firstContact < 0 && !want.empty()) firstContact = pass;
        plain.move(-0.002f, 0.0f);
        cached.move(-0.002f, 0.0f);
    }
    EXPECT_GE(firstContact, 10) << "the plates must start apart for several passes";
    EXPECT_LE(cached.config.counting.calls, plain.config.counting.calls - firstContact + 3);
}

// Aligned cubes 10 cm apart: the broadphase boxes (widened by gContactBreakingThreshold, 2 cm)
// overlap from 4 cm on, the broadphase leaves (widened by 5 cm more) from the start. Approaching
// at 5 mm a pass, then 0.5 mm a pass from 1 cm on: the contact (threshold 3.5 mm) on the same pass,
// with the same points bit for bit, as without the cache, and calls skipped before it.
TEST(SeparatedConvexPairs, AlignedPairSkippedByItsBoxesUntilItsContact) {
    FacingCubes plain(false, 0.1f, 0.0f), cached(true, 0.1f, 0.0f);
    int firstContact = -1;
    float gap = 0.1f;
    for (int pass = 0; gap > -0.001f; ++pass) {
        const std::vector<btManifoldPoint> want = plain.pass();
        expectSamePoints(cached.pass(), want, pass);
        if (pass == 0) {
            ASSERT_EQ(cached.pairs(), 1) << "the broadphase leaves must overlap";
        }
        if (firstContact < 0 && !want.empty()) firstContact = pass;
        const float step = gap > 0.0101f ? 0.005f : 0.0005f;
        plain.move(-step, 0.0f);
        cached.move(-step, 0.0f);
        gap -= step;
    }
    EXPECT_GE(firstContact, 20);
    EXPECT_LT(cached.config.counting.calls, plain.config.counting.calls / 2);
}

// The same approach, face to face, for a pair created while a NewPairMultipoint is alive (perturbed
// contacts for its first passes), against Bullet's perturbed algorithm without the cache.
TEST(SeparatedConvexPairs, NewPairGetsItsPerturbedContactOnTheSamePass) {
    FacingCubes bullet(false, 0.083f), phased(false, 0.083f);
    bullet.config.setConvexConvexMultipointIterations(NewPairMultipoint::kIterations,
                                                      NewPairMultipoint::kMinimumPoints);
    bullet.dispatcher.registerCollisionCreateFunc(
        CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE,
        bullet.config.btDefaultCollisionConfiguration::getCollisionAlgorithmCreateFunc(
            CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE));
    const NewPairMultipoint multipoint(phased.dispatcher, phased.config);
    int firstContact = -1;
    for (int pass = 0; pass < NewPairMultipoint::kPerturbedSteps; ++pass) {
        const std::vector<btManifoldPoint> want = bullet.pass();
        expectSamePoints(phased.pass(), want, pass);
        if (firstContact < 0 && !want.empty()) firstContact = pass;
        bullet.move(-0.01f, 0.0f);
        phased.move(-0.01f, 0.0f);
    }
    EXPECT_GE(firstContact, 5);
    EXPECT_GE(bullet.pass().size(), 3u) << "the perturbed algorithm must have made a full manifold";
}
