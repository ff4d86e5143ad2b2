// SPDX-License-Identifier: Zlib
// Where the rigid-body time of a fracture-heavy scene goes. Replays a scene (default: the demo,
// column_bunny, whose bunny shatters into hundreds of fragments in some of its courses) exactly
// as btfracture-run does (SceneWorld with FractureSceneWorldFactory, the scene and recorder
// listeners, no outputs) and splits each step:
//  - fracture: the engine and the swap (FractureRecorder, the runner's "fracture time");
//  - rigid: the rest of the step (the runner's "rigid-body time"), itself split by Bullet's own
//    profile zones (btSetCustomEnterProfileZoneFunc): broadphase (calculateOverlappingPairs),
//    narrowphase (dispatchAllCollisionPairs), islands, solver (solveConstraints), integration
//    (integrateTransforms, CCD sweeps included), prediction (predictUnconstraintMotion,
//    createPredictiveContacts), activation, and what is left outside Bullet's zones (fragment
//    shapes, separation, the discarded step of a fracture event, energy audits);
//  - narrowphase per shape pair: the dispatcher's near callback timed per pair of Bullet shape
//    types, with the count of pairs left without contact points (apart);
//  - the CCD sweeps: Bullet's swept-sphere tests of the bodies that move more than their CCD
//    motion threshold in a step, in integration and in the predictive contacts.
// Prints METRIC rigid_ms_per_step_demo (rigid ms per step of the default scene; the scene's name
// instead of "demo" for another scene), the rigid share of the step time,
// the bodies at the end and the per-phase times.
//
// Usage: bench_rigid_fragments [SCENE.json] [--steps N] [--hull-vertices N] [--sleeping]
//                              [--bullet-leaves-until STEP [--fraction F]] [--no-profile]
//                              [--trapped-every N]
//   --hull-vertices N  collision hull corner budget of the scene's breakable bodies and their
//                      fragments (0: every corner; default: CollisionShapeOptions)
//   --sleeping         fragment sleeping on (btFractureDynamicsWorld::setFragmentSleeping) even
//                      where the scene's effects.fragment_sleeping leaves it off
//   --bullet-leaves-until STEP
//                      broadphase leaves widened by Bullet's 5 cm before STEP, by the scene
//                      world's SizeScaledBroadphase fraction from STEP on: both leaves from one
//                      state (a STEP past the end: Bullet's leaves throughout)
//   --fraction F       the scaled leaves' fraction of the body's size (default: the scene
//                      world's; inf: Bullet's leaves after STEP too, for the time from STEP on)
//   --no-profile       no zone hooks and no timed near callback: the rigid time as the runner
//                      counts it, without the profile's own cost; prints the first four METRICs
//   --trapped-every N  every N-th step, sorts the convex - GImpact pairs by whether the convex
//                      body's centre lies inside the mesh body (winding number of its mesh > 1/2)
//                      and counts those wholly inside (centre deeper than its bounding radius):
//                      chips caught in a hollow mesh fragment, and their share of that pair
//                      type's narrowphase time (costs O(triangles) per pair; profile only)
#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/ThreadLimit.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/SizeScaledBroadphase.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneFractureListener.h>
#include <btFracture/io/SceneWorld.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <LinearMath/btQuickprof.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace btfracture;

namespace {

using Clock = std::chrono::steady_clock;

// Inclusive time per Bullet profile zone name [s].
struct ZoneTimes {
    std::vector<std::pair<const char*, Clock::time_point>> open;
    std::map<std::string, double> seconds;
    std::map<std::string, long> entries;
};
ZoneTimes zones;

void enterZone(const char* name) {
    zones.open.emplace_back(name, Clock::now());
}
void leaveZone() {
    if (zones.open.empty()) return;
    const auto [name, start] = zones.open.back();
    zones.open.pop_back();
    zones.seconds[name] += std::chrono::duration<double>(Clock::now() - start).count();
    ++zones.entries[name];
}

// Narrowphase time per pair of shape types [s], the pairs' count and the count of those without
// contact points after the call; keyed by the types, named by Bullet's shape names.
struct PairTime {
    std::string name;
    double seconds = 0.0;
    long pairs = 0, apart = 0;
};
std::map<std::pair<int, int>, PairTime> pairTimes;

// Convex - GImpact pairs of the sampled steps (--trapped-every) by where the convex body's centre
// lies: inside the mesh body (and of those, deeper than the convex's bounding radius) or outside.
struct TrappedCount {
    int every = 0, step = 0;
    long inside = 0, wholly = 0, outside = 0;
    double insideSeconds = 0.0, outsideSeconds = 0.0;
};
TrappedCount trapped;

void countTrapped(const btCollisionObject* convex, const btCollisionObject* mesh, double seconds) {
    const btFractureRigidBody* body = btFractureRigidBody::upcast(mesh);
    if (!body) return;
    const btVector3 c = mesh->getWorldTransform().inverse() * convex->getWorldTransform().getOrigin();
    const Eigen::Vector3d centre(c.x(), c.y(), c.z());
    const TriangleMesh& m = body->mesh();
    if (windingNumber(m.vertices, m.triangles, centre) <= 0.5) {
        ++trapped.outside;
        trapped.outsideSeconds += seconds;
        return;
    }
    ++trapped.inside;
    trapped.insideSeconds += seconds;
    double depth = INFINITY;
    for (const auto& t : m.triangles)
        depth = std::min(
            depth,
            (closestPointOnTriangle(centre, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]) - centre)
                .norm());
    btVector3 sphereCentre;
    btScalar radius;
    convex->getCollisionShape()->getBoundingSphere(sphereCentre, radius);
    if (depth > radius) ++trapped.wholly;
}

void timedNearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                       const btDispatcherInfo& info) {
    const auto start = Clock::now();
    btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const btCollisionShape* a =
        static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject)->getCollisionShape();
    const btCollisionShape* b =
        static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject)->getCollisionShape();
    if (b->getShapeType() < a->getShapeType()) std::swap(a, b);
    PairTime& entry = pairTimes[{a->getShapeType(), b->getShapeType()}];
    if (entry.name.empty()) entry.name = std::string(a->getName()) + " - " + b->getName();
    entry.seconds += seconds;
    ++entry.pairs;
    static btManifoldArray manifolds;
    manifolds.resize(0);
    if (pair.m_algorithm) pair.m_algorithm->getAllContactManifolds(manifolds);
    int points = 0;
    for (int i = 0; i < manifolds.size(); ++i) points += manifolds[i]->getNumContacts();
    if (points == 0) ++entry.apart;
    if (trapped.every > 0 && trapped.step % trapped.every == 0 && pair.m_algorithm &&
        b->getShapeType() == GIMPACT_SHAPE_PROXYTYPE && a->isConvex()) {
        const auto* first = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
        const auto* second = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
        if (first->getCollisionShape() != a) std::swap(first, second);
        countTrapped(first, second, seconds);
    }
}

double zone(const char* name) {
    const auto found = zones.seconds.find(name);
    return found == zones.seconds.end() ? 0.0 : found->second;
}

int run(int argc, char** argv) {
    std::string file = std::string(BTFRACTURE_MESH_DIR) + "/../scenes/column_bunny.json";
    bool defaultScene = true, sleeping = false, profile = true;
    int steps = -1, hullVertices = -1, bulletLeavesUntil = 0;
    double fraction = 0.0;  // 0: the scene world's
    for (int i = 1; i < argc; ++i) {
        const bool hasValue = i + 1 < argc;
        if (!std::strcmp(argv[i], "--steps") && hasValue) {
            steps = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--hull-vertices") && hasValue) {
            hullVertices = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--sleeping")) {
            sleeping = true;
        } else if (!std::strcmp(argv[i], "--bullet-leaves-until") && hasValue) {
            bulletLeavesUntil = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--fraction") && hasValue) {
            fraction = std::strtod(argv[++i], nullptr);
            if (!(fraction > 0.0)) {
                std::fprintf(stderr, "bench_rigid_fragments: --fraction must be > 0, got %s\n", argv[i]);
                return 2;
            }
        } else if (!std::strcmp(argv[i], "--trapped-every") && hasValue) {
            trapped.every = std::atoi(argv[++i]);
            if (trapped.every <= 0) {
                std::fprintf(stderr, "bench_rigid_fragments: --trapped-every must be > 0, got %s\n", argv[i]);
                return 2;
            }
        } else if (!std::strcmp(argv[i], "--no-profile")) {
            profile = false;
        } else if (argv[i][0] != '-') {
            file = argv[i];
            defaultScene = false;
        } else {
            std::fprintf(stderr,
                         "usage: bench_rigid_fragments [SCENE.json] [--steps N] [--hull-vertices N] "
                         "[--sleeping] [--bullet-leaves-until STEP [--fraction F]] [--no-profile] "
                         "[--trapped-every N]\n");
            return 2;
        }
    }
    if (trapped.every > 0 && !profile) {
        std::fprintf(stderr,
                     "bench_rigid_fragments: --trapped-every counts in the timed near callback, "
                     "which --no-profile turns off\n");
        return 2;
    }
    Scene scene = readSceneFile(file);
    if (steps > 0) scene.world.steps = steps;
    const ThreadLimit threads(scene.run.threads);
    FractureSceneWorldFactory factory(scene.effects.seed);
    SceneWorld world(scene, factory);
    auto* fractureWorld = dynamic_cast<btFractureDynamicsWorld*>(&world.world());
    auto* dispatcher = dynamic_cast<btCollisionDispatcher*>(world.world().getDispatcher());
    if (!fractureWorld || !dispatcher) {
        std::fprintf(stderr, "bench_rigid_fragments: %s has no breakable body\n", file.c_str());
        return 2;
    }
    auto* broadphase = dynamic_cast<SizeScaledBroadphase*>(world.world().getBroadphase());
    if (!broadphase) {
        std::fprintf(stderr,
                     "bench_rigid_fragments: the scene world's broadphase is not a SizeScaledBroadphase\n");
        return 1;
    }
    const btScalar scaledFraction = fraction > 0.0 ? btScalar(fraction) : broadphase->fraction();
    if (bulletLeavesUntil > 0) broadphase->setFraction(std::numeric_limits<btScalar>::infinity());
    if (sleeping) fractureWorld->setFragmentSleeping(true);
    FractureRecorder recorder;
    FractureRecorderListener names(recorder, scene.world.dt / scene.world.substeps);
    if (hullVertices >= 0)  // the bodies' own shapes keep their budget; their fragments take this
        for (const auto& body : world.bodies())
            if (btFractureRigidBody* b = btFractureRigidBody::upcast(body.rigidBody)) {
                FractureBodySettings settings = b->settings();
                settings.shapeOptions.hullMaxVertices = hullVertices;
                b->setSettings(settings);
            }
    SceneFractureListener sceneListener(names, world);
    fractureWorld->addFractureListener(&sceneListener);
    btEnterProfileZoneFunc* const previousEnter = btGetCurrentEnterProfileZoneFunc();
    btLeaveProfileZoneFunc* const previousLeave = btGetCurrentLeaveProfileZoneFunc();
    if (profile) {
        dispatcher->setNearCallback(timedNearCallback);
        btSetCustomEnterProfileZoneFunc(enterZone);
        btSetCustomLeaveProfileZoneFunc(leaveZone);
    }

    double stepSeconds = 0.0, rigidAfterSwitch = 0.0;
    for (int s = 0; s < scene.world.steps; ++s) {
        if (s == bulletLeavesUntil) broadphase->setFraction(scaledFraction);
        const double fractureBefore = fractureWorld->fractureStatistics().fractureSeconds();
        trapped.step = s;
        Timer timer;
        world.stepFrame();
        const double seconds = timer.seconds();
        stepSeconds += seconds;
        if (s >= bulletLeavesUntil)
            rigidAfterSwitch +=
                seconds - (fractureWorld->fractureStatistics().fractureSeconds() - fractureBefore);
    }
    btSetCustomEnterProfileZoneFunc(previousEnter);
    btSetCustomLeaveProfileZoneFunc(previousLeave);
    const double fracture = fractureWorld->fractureStatistics().fractureSeconds();
    const double rigid = stepSeconds - fracture;
    const double perStep = 1e3 / scene.world.steps;
    int active = 0, asleep = 0, hulls = 0, maxCorners = 0;
    long corners = 0;
    for (const auto& body : world.bodies()) {
        if (body.rigidBody->isStaticOrKinematicObject()) continue;
        (body.rigidBody->isActive() ? active : asleep) += 1;
        if (const auto* hull = dynamic_cast<const btConvexHullShape*>(body.rigidBody->getCollisionShape())) {
            ++hulls;
            corners += hull->getNumPoints();
            maxCorners = std::max(maxCorners, hull->getNumPoints());
        }
    }
    const std::string tag = defaultScene ? std::string("demo") : scene.name;
    const FractureStatistics& stats = fractureWorld->fractureStatistics();
    std::printf("scene %s: %d steps, %d fracture events, %zu bodies at the end (%d awake, %d asleep)\n",
                file.c_str(), scene.world.steps, recorder.events(), world.bodies().size(), active, asleep);
    // A hull's corners are what every support query of GJK and of the CCD sweeps loops over.
    std::printf("convex hull bodies at the end %d, %.1f corners on average, %d at most\n", hulls,
                hulls > 0 ? double(corners) / hulls : 0.0, maxCorners);
    std::printf("METRIC rigid_ms_per_step_%s %.3f ms\n", tag.c_str(), rigid * perStep);
    std::printf("METRIC rigid_share_of_wall_%s %.3f fraction\n", tag.c_str(), rigid / stepSeconds);
    std::printf("METRIC fracture_ms_per_step_%s %.3f ms\n", tag.c_str(), fracture * perStep);
    std::printf("METRIC bodies_at_end_%s %zu bodies\n", tag.c_str(), world.bodies().size());
    if (bulletLeavesUntil > 0 && bulletLeavesUntil < scene.world.steps)
        std::printf("rigid from step %d on (leaves widened by %g of the body): %.3f ms per step\n",
                    bulletLeavesUntil, double(scaledFraction),
                    1e3 * rigidAfterSwitch / (scene.world.steps - bulletLeavesUntil));
    if (!profile) return 0;
    std::printf("engine calls %llu (%llu without fragments), Bullet's own steps %.3f ms per step\n",
                static_cast<unsigned long long>(stats.engineCalls),
                static_cast<unsigned long long>(stats.engineCalls - stats.fractureEvents),
                zone("internalSingleStepSimulation") * perStep);
    // Bullet's step, by zone (inclusive times; CCD sweeps run inside integrateTransforms).
    const double broad = zone("updateAabbs") + zone("calculateOverlappingPairs");
    const double narrow = zone("dispatchAllCollisionPairs");
    const double islands = zone("calculateSimulationIslands"), solver = zone("solveConstraints");
    const double integrate = zone("integrateTransforms");
    const double predict = zone("predictUnconstraintMotion") + zone("createPredictiveContacts");
    const double activation = zone("updateActivationState");
    const double rest = rigid - broad - narrow - islands - solver - integrate - predict - activation;
    const std::pair<const char*, double> phases[] = {{"broadphase", broad},        {"narrowphase", narrow},
                                                     {"islands", islands},         {"solver", solver},
                                                     {"integrate_ccd", integrate}, {"predict", predict},
                                                     {"activation", activation},   {"outside_bullet", rest}};
    for (const auto& [name, seconds] : phases)
        std::printf("METRIC rigid_%s_ms_per_step_%s %.3f ms\n", name, tag.c_str(), seconds * perStep);
    std::vector<PairTime> pairs;
    for (const auto& [types, entry] : pairTimes) pairs.push_back(entry);
    std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.seconds > b.seconds; });
    for (const PairTime& entry : pairs)
        std::printf(
            "  narrowphase %-40s %8.3f ms per step, %8.1f pairs per step (%8.1f without "
            "contact points), %6.2f us per pair\n",
            entry.name.c_str(), entry.seconds * perStep, double(entry.pairs) / scene.world.steps,
            double(entry.apart) / scene.world.steps,
            entry.pairs > 0 ? 1e6 * entry.seconds / double(entry.pairs) : 0.0);
    if (trapped.every > 0) {
        const long pairs = trapped.inside + trapped.outside;
        const double total = trapped.insideSeconds + trapped.outsideSeconds;
        std::printf(
            "  convex - GImpact pairs in every %d-th step: %ld, %ld with the convex centre inside the "
            "mesh body (%ld wholly inside), %.1f us each against %.1f outside, %.3f of the time\n",
            trapped.every, pairs, trapped.inside, trapped.wholly,
            trapped.inside > 0 ? 1e6 * trapped.insideSeconds / double(trapped.inside) : 0.0,
            trapped.outside > 0 ? 1e6 * trapped.outsideSeconds / double(trapped.outside) : 0.0,
            total > 0.0 ? trapped.insideSeconds / total : 0.0);
    }
    // Bullet's swept-sphere tests of the bodies that move more than their CCD motion threshold.
    for (const char* sweep : {"CCD motion clamping", "predictive convexSweepTest"}) {
        const auto found = zones.entries.find(sweep);
        const long count = found == zones.entries.end() ? 0 : found->second;
        std::printf("  %-28s %8.3f ms per step, %8.1f sweeps per step, %6.2f us per sweep\n", sweep,
                    zone(sweep) * perStep, double(count) / scene.world.steps,
                    count > 0 ? 1e6 * zone(sweep) / double(count) : 0.0);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {  // a scene or mesh that cannot be read, named in the message
        std::fprintf(stderr, "bench_rigid_fragments: %s\n", e.what());
        return 1;
    }
}
