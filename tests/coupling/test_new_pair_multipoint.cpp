// SPDX-License-Identifier: Zlib
// NewPairMultipoint: a pair created while it is alive gets Bullet's perturbed contacts (a full
// manifold in one pass) for its first kPerturbedSteps narrowphase passes, then one new point per
// pass between moving bodies; against static geometry it keeps the full manifold.
#include <btFracture/dynamics/NewPairMultipoint.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <gtest/gtest.h>

#include <vector>

using namespace btfracture;

namespace {

// A 0.2 m cube (a convex hull) resting face down, 1 mm deep, on another in a collision world.
struct StackedCubes {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btCollisionWorld world{&dispatcher, &broadphase, &config};
    btConvexHullShape shape;
    btCollisionObject lower, upper;

    explicit StackedCubes(bool lowerIsStatic) {
        for (int k = 0; k < 8; ++k)
            shape.addPoint(btVector3(k & 1 ? 0.1f : -0.1f, k & 2 ? 0.1f : -0.1f, k & 4 ? 0.1f : -0.1f));
        shape.setMargin(0.0f);
        place(lower, 0.0f, lowerIsStatic);
        place(upper, 0.199f, false);
    }
    ~StackedCubes() {
        world.removeCollisionObject(&upper);
        world.removeCollisionObject(&lower);
    }
    void place(btCollisionObject& object, float y, bool isStatic) {
        object.setCollisionShape(&shape);
        btTransform t;
        t.setIdentity();
        t.setOrigin(btVector3(0, y, 0));
        object.setWorldTransform(t);
        object.setCollisionFlags(isStatic ? btCollisionObject::CF_STATIC_OBJECT : 0);
        world.addCollisionObject(&object);
    }
    // One narrowphase pass on cleared manifolds: the contact points that pass found.
    int pass() {
        for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
            dispatcher.getManifoldByIndexInternal(m)->clearManifold();
        world.performDiscreteCollisionDetection();
        int count = 0;
        for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
            count += dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
        return count;
    }
};

// Points per pass; the pair is created in the first pass, with a NewPairMultipoint alive.
std::vector<int> pointsPerPass(bool lowerIsStatic, int passes) {
    StackedCubes cubes(lowerIsStatic);
    std::vector<int> points;
    {
        const NewPairMultipoint multipoint(cubes.dispatcher, cubes.config);
        points.push_back(cubes.pass());
    }
    while (static_cast<int>(points.size()) < passes) points.push_back(cubes.pass());
    return points;
}

}  // namespace

TEST(NewPairMultipoint, MovingPairsPerturbOnlyWhileNew) {
    const int n = NewPairMultipoint::kPerturbedSteps;
    const std::vector<int> points = pointsPerPass(false, n + 3);
    for (int pass = 0; pass < n; ++pass) EXPECT_GE(points[pass], 3) << "pass " << pass;
    for (int pass = n; pass < n + 3; ++pass) EXPECT_EQ(points[pass], 1) << "pass " << pass;
}

TEST(NewPairMultipoint, PairsWithStaticGeometryKeepPerturbing) {
    const int n = NewPairMultipoint::kPerturbedSteps;
    const std::vector<int> points = pointsPerPass(true, n + 3);
    for (int pass = 0; pass < n + 3; ++pass) EXPECT_GE(points[pass], 3) << "pass " << pass;
}

// A pair created after the NewPairMultipoint is gone gets Bullet's default: one point per pass.
TEST(NewPairMultipoint, PairsCreatedOutsideItKeepBulletsDefault) {
    StackedCubes cubes(false);
    { const NewPairMultipoint multipoint(cubes.dispatcher, cubes.config); }  // registered, put back
    EXPECT_EQ(cubes.pass(), 1);
    EXPECT_EQ(cubes.dispatcher.getNumManifolds(), 1);
}
