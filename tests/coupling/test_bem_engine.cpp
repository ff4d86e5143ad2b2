// SPDX-License-Identifier: Zlib
// The physical engine end to end (paper §3-§5): a steel ball breaks a glass slab through the
// BEM, the crack solver and the level set; mass and momentum across the event, the threshold,
// and determinism.
#include "CouplingScene.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/geometry/LevelSetBody.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

using namespace btfracture;
using namespace btfracture::test;

namespace {

struct EventProbe : FractureListener {
    explicit EventProbe(btDiscreteDynamicsWorld& w) : world(w) {}
    void onFractureEvent(btFractureRigidBody&, const std::vector<btFractureRigidBody*>& fragments,
                         const FractureEventInfo& info) override {
        ++events;
        pieces += static_cast<int>(fragments.size());
        atSwap = probe(world);
        timings = info.engineTimings;
    }
    btDiscreteDynamicsWorld& world;
    int events = 0, pieces = 0;
    EngineTimings timings;  // of the last event
    WorldProbe atSwap;
};

// Steps until the first fracture event, at most maxSteps; returns the world probed just before
// that step (what the event's swap is compared with).
WorldProbe stepUntilFirstEvent(Scene& scene, const EventProbe& listener, int maxSteps) {
    WorldProbe before;
    for (int i = 0; i < maxSteps && listener.events == 0; ++i) {
        before = probe(*scene.world);
        scene.step();
    }
    return before;
}

}  // namespace

TEST(BemEngine, SteelBallBreaksGlassSlabConservingMassAndMomentum) {
    SceneOptions options;
    options.physicalEngine = true;
    Scene scene(options);
    EventProbe listener(*scene.world);
    scene.world->addFractureListener(&listener);
    const double slabMass = 1.0 / double(scene.slab->getInvMass());
    const WorldProbe before = stepUntilFirstEvent(scene, listener, 20);
    ASSERT_EQ(listener.events, 1);
    const FractureStatistics& stats = scene.world->fractureStatistics();
    EXPECT_EQ(stats.bemBuilds, 1u);
    EXPECT_GE(listener.pieces, 2);
    // The slab split, so some crack front grew: K_eff > K_c there (PropagationLaw.h).
    std::printf("glass slab: largest K/K_c %.3g\n", stats.maxLoadRatio);
    EXPECT_GT(stats.maxLoadRatio, 1.0);
    // Mass: fragments measured on the level set (voxel 3 mm here) against the slab's exact mass;
    // dust too small to mesh is dropped (logged). Momentum: the swap itself is exact.
    const double massError = std::abs(listener.atSwap.mass - before.mass) / slabMass;
    const double momentumError = (listener.atSwap.linear - before.linear).norm() / before.linear.norm();
    std::printf("glass slab: %d fragments, mass change %.3f %% of the slab, momentum change %.2e relative\n",
                listener.pieces, 100 * massError, momentumError);
    EXPECT_LT(massError, 0.01);
    EXPECT_LT(momentumError, 0.01);  // only through the mass of dropped dust and level-set volumes
    scene.step(120);
    for (btFractureRigidBody* f : scene.fragments())
        EXPECT_GT(f->getWorldTransform().getOrigin().y(), -0.05) << f->name() << " fell through the ground";
}

// Whether the ball breaks the slab must not hang on the details of one BEM mesh. The slab is 5 cm
// thick and a BEM edge about 3 cm, so most of each crack's front meets a face in the first step;
// when such nodes stopped for good, the few left inside decided the outcome: at 10 m/s only 3 of
// these 9 targets (900 ... 1,100 triangles) gave an event, 6 none. Front ends now slide along the
// faces (fracture/CrackGrowth.h): every target breaks (measured: 3-14 pieces, chips of 0.2-2 %).
TEST(BemEngine, SlabBreaksAtEveryNearbyBemResolution) {
    for (const int target : {900, 950, 980, 990, 1000, 1010, 1020, 1050, 1100}) {
        SceneOptions options;
        options.physicalEngine = true;
        options.bemTriangleTarget = target;
        Scene scene(options);
        EventProbe listener(*scene.world);
        scene.world->addFractureListener(&listener);
        stepUntilFirstEvent(scene, listener, 20);
        std::printf("BEM target %d: %d events, %d pieces\n", target, listener.events, listener.pieces);
        EXPECT_EQ(listener.events, 1) << "BEM target " << target;
        EXPECT_GE(listener.pieces, 2) << "BEM target " << target;
    }
}

// With FULL's seeds on the surface (CrackSettings::surfaceSeeds; HYBRID starts as FULL) the ball
// breaks the slab too, at nearby BEM resolutions and at 0.9 of the speed.
TEST(BemEngine, SurfaceSeedsBreakTheSlab) {
    for (const double speed : {1.0, 0.9})
        for (const int target : {950, 1000, 1050}) {
            SceneOptions options;
            options.physicalEngine = true;
            options.surfaceSeeds = true;
            options.bemTriangleTarget = target;
            options.ballSpeed *= speed;
            Scene scene(options);
            EventProbe listener(*scene.world);
            scene.world->addFractureListener(&listener);
            stepUntilFirstEvent(scene, listener, 20);
            std::printf("surface seeds, BEM target %d, %.1f x speed: %d events, %d pieces\n", target, speed,
                        listener.events, listener.pieces);
            EXPECT_EQ(listener.events, 1) << "BEM target " << target << ", " << speed << " x speed";
            EXPECT_GE(listener.pieces, 2) << "BEM target " << target << ", " << speed << " x speed";
        }
}

TEST(BemEngine, SlowBallBuildsNothing) {
    SceneOptions options;
    options.physicalEngine = true;
    options.ballSpeed = 0.3;
    Scene scene(options);
    scene.step(60);
    EXPECT_EQ(scene.world->fractureStatistics().bemBuilds, 0u);
    EXPECT_EQ(scene.world->fractureStatistics().fractureEvents, 0u);
    EXPECT_EQ(scene.world->fractureStatistics().maxLoadRatio, 0.0);
}

TEST(BemEngine, SameImpactTwiceGivesIdenticalFragments) {
    auto run = [] {
        SceneOptions options;
        options.physicalEngine = true;
        Scene scene(options);
        scene.step(30);
        return scene.fragmentPoses();
    };
    expectBitIdentical(run(), run());
}

// Voxel-resolution fronts (the default) against the coarse-sheet cut: the markers' swept surface
// cut into the slab's level set splits it, conserving mass like the first test, and identically
// on a rerun. Crack slabs count as material: the level-set volume stays. The fragment counts are
// printed, not compared: they differ between the two cuts and between build flavours.
TEST(BemEngine, VoxelFrontsSplitTheSlabDeterministically) {
    struct Cut {
        int cuts = 0, events = 0, pieces = 0;
        std::vector<int> ids;
        double volumeRatio = 0.0, massError = 0.0;
        EngineTimings timings;
        std::vector<btTransform> poses;
    };
    auto run = [](bool voxelFronts) {
        SceneOptions options;
        options.withEngine = false;
        Scene scene(options);
        BemFractureEngineSettings settings;
        settings.voxelFronts = voxelFronts;
        auto engine = std::make_unique<BemFractureEngine>(settings);
        Cut cut;
        engine->setCutObserver([&cut](const btFractureRigidBody&, const LevelSetBody& levelSet) {
            if (++cut.cuts > 1) return;  // the slab's first cut
            cut.ids = levelSet.crackIds();
            cut.volumeRatio = levelSet.massProperties().volume / levelSet.originalVolume();
        });
        scene.world->setFractureEngine(std::move(engine));
        EventProbe listener(*scene.world);
        scene.world->addFractureListener(&listener);
        const double slabMass = 1.0 / double(scene.slab->getInvMass());
        const WorldProbe before = stepUntilFirstEvent(scene, listener, 30);
        cut.events = listener.events;
        cut.pieces = listener.pieces;
        cut.timings = listener.timings;
        cut.massError = std::abs(listener.atSwap.mass - before.mass) / slabMass;
        cut.poses = scene.fragmentPoses();
        return cut;
    };
    const Cut a = run(true), b = run(true), coarse = run(false);
    std::printf(
        "voxel fronts: %d fragments (coarse sheet: %d), %zu cracks, mass change %.3f %% (coarse %.3f "
        "%%), level-set volume ratio %.9f\n",
        a.pieces, coarse.pieces, a.ids.size(), 100 * a.massError, 100 * coarse.massError, a.volumeRatio);
    std::printf("event time: crack growth %.2f s, cut and fragments %.2f s (coarse sheet: %.2f s, %.2f s)\n",
                a.timings.fracture, a.timings.geometry, coarse.timings.fracture, coarse.timings.geometry);
    ASSERT_EQ(a.events, 1);
    ASSERT_EQ(coarse.events, 1);
    EXPECT_GE(a.pieces, 2);
    EXPECT_LT(a.massError, 0.01);            // dropped dust and level-set volumes, as above
    EXPECT_NEAR(a.volumeRatio, 1.0, 0.005);  // level-set volume against the exact box, cracks included
    EXPECT_GE(a.ids.size(), 2u);
    EXPECT_EQ(a.cuts, b.cuts);
    EXPECT_EQ(a.ids, b.ids);
    EXPECT_EQ(a.volumeRatio, b.volumeRatio);
    EXPECT_EQ(a.pieces, b.pieces);
    expectBitIdentical(a.poses, b.poses);
}

namespace {

// Engine calls without a world: two 20 x 5 x 20 cm glass slabs at 300 BEM triangles, an engine
// with the given idle budget, and a contact on the slabs' top face (its impulse set by the test).
struct TwoSlabs {
    explicit TwoSlabs(double idleMatrixBudgetMB) : engine(settingsWith(idleMatrixBudgetMB)) {
        contact.point = Eigen::Vector3d(0.02, 0.025, 0.01);
        contact.direction = -Eigen::Vector3d::UnitY();
        contact.duration = 5e-5;
    }
    static BemFractureEngineSettings settingsWith(double idleMatrixBudgetMB) {
        BemFractureEngineSettings settings;
        settings.idleMatrixBudgetMB = idleMatrixBudgetMB;
        return settings;
    }
    static FractureBodySettings slabSettings() {
        FractureBodySettings settings;
        settings.bemTriangleTarget = 300;
        return settings;
    }
    inline static const btBoxShape box{btVector3(btScalar(0.1), btScalar(0.025), btScalar(0.1))};
    BemFractureEngine engine;
    btFractureRigidBody a{Material::glass(), box, slabSettings()}, b{Material::glass(), box, slabSettings()};
    BodyContact contact;
};

}  // namespace

// idleMatrixBudgetMB: with a budget of 0, slab A's BEM matrices are released while slab B
// breaks and assembled again for A's next event; that event must come out exactly as with every
// matrix kept (the assembly is deterministic). Bodies called within the last steps keep theirs.
TEST(BemEngine, ReleasedMatricesAreRebuiltIdentically) {
    struct Run {
        FractureOutcome outcome;
        int released = 0, rebuilt = 0, freedOnBreak = 0;
    };
    auto run = [](double budgetMB) {
        TwoSlabs slabs(budgetMB);
        auto& [engine, a, b, contact] = slabs;
        Run r;
        std::vector<std::string> messages;
        const LogLevel level = logLevel();
        setLogLevel(LogLevel::Debug);
        setLogSink([&](LogLevel, const std::string& m) { messages.push_back(m); });
        FractureStatistics stats;  // its steps: 10 apart, so no body counts as in lasting contact
        contact.impulse = 1e-3;    // builds the BEM, grows nothing
        engine.fracture(a, {contact}, stats);
        stats.steps += 10;
        engine.fracture(b, {contact}, stats);
        stats.steps += 10;
        contact.impulse = 5.0;
        r.outcome = engine.fracture(a, {contact}, stats);
        setLogSink(nullptr);
        setLogLevel(level);
        for (const std::string& m : messages) {
            r.released += m.find("are released to keep") != std::string::npos;
            r.rebuilt += m.find("assembled and factored again") != std::string::npos;
            r.freedOnBreak += m.find("are released: it broke into fragments") != std::string::npos;
        }
        return r;
    };
    const Run kept = run(std::numeric_limits<double>::infinity()), released = run(0.0);
    std::printf("struck again: %d crack triangles, %zu fragments, largest K/K_c %.4g\n",
                kept.outcome.crackTriangles, kept.outcome.fragments.size(), kept.outcome.maxLoadRatio);
    EXPECT_EQ(kept.released, 0);
    EXPECT_EQ(kept.rebuilt, 0);
    EXPECT_EQ(kept.freedOnBreak, 0);  // a piece of > 95 % of A takes A's state, matrices and all
    EXPECT_EQ(released.released, 3);  // A's before B's call, B's before A's second, A's before its cut
    EXPECT_EQ(released.rebuilt, 1);
    EXPECT_GT(kept.outcome.maxLoadRatio, 1.0);  // the second strike grows cracks
    EXPECT_EQ(kept.outcome.maxLoadRatio, released.outcome.maxLoadRatio);
    EXPECT_EQ(kept.outcome.crackTriangles, released.outcome.crackTriangles);
    ASSERT_EQ(kept.outcome.fragments.size(), released.outcome.fragments.size());
    for (std::size_t k = 0; k < kept.outcome.fragments.size(); ++k)
        EXPECT_EQ(kept.outcome.fragments[k].volume, released.outcome.fragments[k].volume) << "fragment " << k;
}

// A body that breaks apart (no piece of > 95 % of it takes its state over) frees its matrices at
// once, whatever the budget: it is gone from the world.
TEST(BemEngine, BodyThatBreaksApartFreesItsMatrices) {
    TwoSlabs slabs(std::numeric_limits<double>::infinity());
    auto& [engine, a, b, contact] = slabs;
    contact.impulse = 50.0;  // shatters the slab
    int freed = 0;
    const LogLevel level = logLevel();
    setLogLevel(LogLevel::Debug);
    setLogSink([&](LogLevel, const std::string& m) {
        freed += m.find("are released: it broke into fragments") != std::string::npos;
    });
    FractureStatistics stats;
    const FractureOutcome outcome = engine.fracture(a, {contact}, stats);
    setLogSink(nullptr);
    setLogLevel(level);
    const auto keeps = [](const FragmentSpec& f) { return f.cls == FragmentSpec::Class::KeepsParentSolver; };
    std::printf("%zu fragments, a piece keeps the state: %d\n", outcome.fragments.size(),
                int(std::any_of(outcome.fragments.begin(), outcome.fragments.end(), keeps)));
    ASSERT_GE(outcome.fragments.size(), 2u);
    // On another CPU's course a large piece may still take the state over: then it keeps them.
    EXPECT_EQ(freed, std::any_of(outcome.fragments.begin(), outcome.fragments.end(), keeps) ? 0 : 1);
}

TEST(BemEngine, BodiesInLastingContactKeepTheirMatrices) {
    TwoSlabs slabs(0.0);
    auto& [engine, a, b, contact] = slabs;
    contact.impulse = 1e-3;
    int released = 0;
    setLogSink(
        [&](LogLevel, const std::string& m) { released += m.find("are released") != std::string::npos; });
    FractureStatistics stats;
    for (int step = 0; step < 6; ++step, ++stats.steps) {  // both pressed at every step
        engine.fracture(a, {contact}, stats);
        engine.fracture(b, {contact}, stats);
    }
    setLogSink(nullptr);
    EXPECT_EQ(released, 0);
}

TEST(BemEngine, NegativeMatrixBudgetIsRejected) {
    BemFractureEngineSettings settings;
    settings.idleMatrixBudgetMB = -1.0;
    EXPECT_THROW(BemFractureEngine{settings}, Error);
}
