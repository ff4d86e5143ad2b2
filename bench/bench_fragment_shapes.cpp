// SPDX-License-Identifier: Zlib
// Collision shapes for non-convex fragments: HACD convex decomposition (btCompoundShape of
// convex hulls) against btGImpactMeshShape (CollisionShapeBuilder.h). Tori stand in for
// non-convex fragments.
//   1. build time per shape at three mesh resolutions, and of the plane-split pieces used above
//      HACD's triangle limit (geometry/SplitDecomposition.h) at 1,536 and 5,000 triangles;
//   2. a pile: 24 tori dropped into a bin, 3 s at 240 Hz: time per step, and afterwards how
//      still the pile is (mean speed over the last 0.25 s) and how many tori sank into the
//      ground or into each other (a torus centre below its tube radius = tunnelled).
// Prints METRIC lines; the default in CollisionShapeBuilder.h (decomposition up to 600
// triangles, GImpact above) rests on these numbers.
#include <btFracture/core/Primitives.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/CollisionShapeBuilder.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/SplitDecomposition.h>

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace btfracture;

namespace {

const char* tag(CollisionShapeKind kind) {
    return kind == CollisionShapeKind::GImpactMesh ? "gimpact" : "hacd";
}

struct PileResult {
    double stepMs = 0.0, meanSpeed = 0.0;
    int sunk = 0;
};

PileResult pile(CollisionShapeKind kind, const TriangleMesh& mesh, double tube) {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btFractureDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, btScalar(-9.81), 0));
    btBoxShape groundShape(btVector3(2, btScalar(0.5), 2));
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
    ground.getWorldTransform().setOrigin(btVector3(0, btScalar(-0.5), 0));
    world.addRigidBody(&ground);
    FractureBodySettings settings;
    settings.fracturable = false;
    settings.concaveShapeKind = kind;
    std::vector<std::unique_ptr<btFractureRigidBody>> bodies;
    // The first body builds the shape's data; the others reuse its mesh (each owns a shape).
    for (int i = 0; i < 24; ++i) {
        const btScalar x = btScalar(-0.25 + 0.25 * (i % 3)), z = btScalar(-0.125 + 0.25 * ((i / 3) % 2));
        const btScalar y = btScalar(0.1 + 0.12 * (i / 6));
        btTransform pose(
            btQuaternion(btVector3(1, 0, btScalar(0.3 * (i % 4))).normalized(), btScalar(1.2 + 0.2 * i)),
            btVector3(x, y, z));
        bodies.push_back(std::make_unique<btFractureRigidBody>(Material::glass(), mesh, settings, pose));
        world.addRigidBody(bodies.back().get());
    }
    const int steps = 720, tail = 60;
    const btScalar dt = btScalar(1.0 / 240.0);
    Timer timer;
    double speedSum = 0.0;
    for (int s = 0; s < steps; ++s) {
        world.stepSimulation(dt, 1, dt);
        if (s >= steps - tail)
            for (auto& b : bodies) speedSum += double(b->getLinearVelocity().length());
    }
    PileResult r;
    r.stepMs = 1e3 * timer.seconds() / steps;
    r.meanSpeed = speedSum / (tail * bodies.size());
    for (auto& b : bodies)
        if (double(b->getWorldTransform().getOrigin().y()) < 0.5 * tube) ++r.sunk;
    for (auto& b : bodies) world.removeRigidBody(b.get());
    world.removeRigidBody(&ground);
    return r;
}

}  // namespace

int main() {
    const double R = 0.08, r = 0.03;
    for (const int major : {24, 32, 48}) {
        const TriangleMesh mesh = makeTorus(R, r, major, major / 2);
        for (const CollisionShapeKind kind :
             {CollisionShapeKind::ConvexDecomposition, CollisionShapeKind::GImpactMesh}) {
            Timer timer;
            CollisionShapeOptions options;
            options.decompositionTriangleLimit = 1 << 30;  // measure HACD at every size
            const auto shape = buildCollisionShape(mesh, kind, options);
            std::printf("METRIC shape_build_ms_%s_%zu %.2f ms  (%zu convex pieces)\n", tag(kind),
                        mesh.triangles.size(), 1e3 * timer.seconds(), shape->convexPieces().size());
        }
    }
    for (const int major : {48, 100}) {
        TriangleMesh mesh = makeTorus(R, r, major, major == 48 ? 16 : 25);
        mesh.name = "torus";
        Timer timer;
        const SplitDecomposition split = splitDecomposition(mesh);
        std::printf(
            "METRIC split_build_ms_%zu %.2f ms  (%zu convex pieces, hull volume %.3f of the mesh's)\n",
            mesh.triangles.size(), 1e3 * timer.seconds(), split.pieces.size(),
            split.hullVolume / split.meshVolume);
    }
    const TriangleMesh mesh = makeTorus(R, r, 24, 12);
    for (const CollisionShapeKind kind :
         {CollisionShapeKind::ConvexDecomposition, CollisionShapeKind::GImpactMesh}) {
        const PileResult p = pile(kind, mesh, r);
        std::printf("METRIC pile_step_ms_%s %.3f ms\n", tag(kind), p.stepMs);
        std::printf("METRIC pile_resting_speed_%s %.4f m/s\n", tag(kind), p.meanSpeed);
        std::printf("METRIC pile_sunk_%s %d bodies\n", tag(kind), p.sunk);
    }
    return 0;
}
