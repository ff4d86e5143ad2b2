// SPDX-License-Identifier: Zlib
#include "TestMeshes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/dynamics/BulletEigen.h>
#include <btFracture/dynamics/CollisionShapeBuilder.h>
#include <btFracture/dynamics/FragmentSeparation.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/ConvexHull.h>

#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletDynamicsCommon.h>

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using namespace btfracture;

TEST(CollisionShapes, ConvexHullIsShrunkByItsMargin) {
    const TriangleMesh box = makeBox(Eigen::Vector3d(0.2, 0.1, 0.3), 0.0, "box");
    CollisionShapeOptions options;
    options.margin = 0.01;
    const auto storage = buildCollisionShape(box, CollisionShapeKind::ConvexHull, options);
    ASSERT_EQ(storage->convexPieces().size(), 1u);
    const ConvexPolytope& piece = storage->convexPieces().front();
    EXPECT_NEAR(piece.margin, 0.01, 1e-6);
    // Shrunk hull + margin reaches the original faces: support along +x is 0.2.
    double maxX = -1.0;
    for (const auto& p : piece.points) maxX = std::max(maxX, p.x());
    EXPECT_NEAR(maxX + piece.margin, 0.2, 1e-4);  // Bullet's shrink is approximate
    // Bullet's own support mapping (hull + margin) agrees.
    const auto* convex = static_cast<const btConvexShape*>(storage->shape());
    EXPECT_NEAR(double(convex->localGetSupportingVertex(btVector3(1, 0, 0)).x()), 0.2, 1e-4);
}

// A round chip's hull keeps options.hullMaxVertices corners (Bullet scans every corner per
// support query); 0 (the default) keeps them all; a budget below a tetrahedron is refused.
TEST(CollisionShapes, ConvexHullKeepsItsCornerBudget) {
    const TriangleMesh ball = makeGeodesicSphere(0.05, 8);
    ASSERT_GT(ball.vertices.size(), 200u);
    CollisionShapeOptions options;
    options.hullMaxVertices = 48;
    const auto budgeted = buildCollisionShape(ball, CollisionShapeKind::ConvexHull, options);
    EXPECT_LE(budgeted->convexPieces().front().points.size(), std::size_t(options.hullMaxVertices));
    EXPECT_EQ(static_cast<const btConvexHullShape*>(budgeted->shape())->getNumPoints(),
              int(budgeted->convexPieces().front().points.size()));
    options.hullMaxVertices = 0;
    const auto full = buildCollisionShape(ball, CollisionShapeKind::ConvexHull, options);
    EXPECT_GT(full->convexPieces().front().points.size(), 200u);
    // Along any axis the budgeted hull + margin reaches within 10 % of the radius of the full one
    // (geometry test HullBudget.RoundChipStaysFaithful).
    for (const btVector3 axis : {btVector3(1, 0, 0), btVector3(0, 1, 0), btVector3(0.6f, 0, 0.8f)}) {
        const double a = double(
            static_cast<const btConvexShape*>(budgeted->shape())->localGetSupportingVertex(axis).dot(axis));
        const double b = double(
            static_cast<const btConvexShape*>(full->shape())->localGetSupportingVertex(axis).dot(axis));
        EXPECT_LE(a, b + 1e-6);
        EXPECT_GT(a, b - 0.10 * 0.05);
    }
    options.hullMaxVertices = 3;
    EXPECT_THROW(buildCollisionShape(ball, CollisionShapeKind::ConvexHull, options), Error);
}

TEST(CollisionShapes, DecompositionCoversANonConvexMesh) {
    const TriangleMesh l = test::lShape(0.1, 0.02);
    const auto storage = buildCollisionShape(l, CollisionShapeKind::ConvexDecomposition);
    ASSERT_GE(storage->convexPieces().size(), 2u);
    // The pieces' hulls together have about the L's volume (no piece spans the notch).
    double volume = 0.0;
    for (const auto& piece : storage->convexPieces()) {
        std::vector<Eigen::Vector3d> inflated = piece.points;
        volume += computeMassProperties(convexHullMesh(inflated, "piece")).volume;
    }
    const double exact = computeMassProperties(l).volume;
    EXPECT_LT(volume, 1.1 * exact);
    EXPECT_GT(volume, 0.6 * exact);  // shrunk by the margin
    // Above HACD's triangle limit the mesh is split by planes (HACD would take seconds): the L
    // splits at its inner corner (and maybe again, where the sampled volumes err), the torus into
    // several pieces within the budget.
    CollisionShapeOptions split;
    split.decompositionTriangleLimit = 0;
    const auto splitL = buildCollisionShape(l, CollisionShapeKind::ConvexDecomposition, split);
    EXPECT_EQ(splitL->kind(), CollisionShapeKind::ConvexDecomposition);
    EXPECT_GE(splitL->convexPieces().size(), 2u);
    EXPECT_LE(splitL->convexPieces().size(), 4u);
    const TriangleMesh ring = makeTorus(0.1, 0.03, 32, 12);  // 768 triangles
    const auto splitRing = buildCollisionShape(ring, CollisionShapeKind::ConvexDecomposition);
    EXPECT_EQ(splitRing->kind(), CollisionShapeKind::ConvexDecomposition);
    EXPECT_GE(splitRing->convexPieces().size(), 4u);
    EXPECT_LE(static_cast<int>(splitRing->convexPieces().size()), CollisionShapeOptions{}.splitMaxPieces);
    const auto gimpact = buildCollisionShape(l, CollisionShapeKind::GImpactMesh);
    EXPECT_TRUE(gimpact->convexPieces().empty());
    EXPECT_EQ(gimpact->shape()->getShapeType(), GIMPACT_SHAPE_PROXYTYPE);
}

// A GImpact mesh above options.gimpactMaxTriangles collides as the mesh decimated to that budget;
// a budget of 0 keeps every triangle. Either way the mesh lies a margin inside the surface
// (MeshInset.h), so that mesh + margin, what Bullet collides with, is the surface.
TEST(CollisionShapes, GImpactMeshKeepsItsTriangleBudget) {
    const double R = 0.1, r = 0.03;
    const TriangleMesh ring = makeTorus(R, r, 96, 32);  // 6,144 triangles
    // The triangles Bullet collides with (a mesh part reads its arrays while locked).
    const auto triangles = [](const CollisionShapeStorage& s) {
        const auto* gimpact = static_cast<const btGImpactMeshShape*>(s.shape());
        std::vector<std::array<Eigen::Vector3d, 3>> out;
        for (int p = 0; p < gimpact->getMeshPartCount(); ++p) {
            const btGImpactMeshShapePart* part = gimpact->getMeshPart(p);
            part->lockChildShapes();
            const btPrimitiveManagerBase* primitives = part->getPrimitiveManager();
            for (int t = 0; t < primitives->get_primitive_count(); ++t) {
                btPrimitiveTriangle triangle;
                primitives->get_primitive_triangle(t, triangle);
                out.push_back({toEigen(triangle.m_vertices[0]), toEigen(triangle.m_vertices[1]),
                               toEigen(triangle.m_vertices[2])});
            }
            part->unlockChildShapes();
        }
        return out;
    };
    // Signed distance of a point to the torus surface (axis z; negative inside).
    const auto signedDistance = [&](const Eigen::Vector3d& p) {
        return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r;
    };
    // Every corner and centroid + margin lies on the surface: no more than 0.2 margin outside,
    // no more than 0.35 margin inside (the sag of the decimated mesh's chords, 0.27 margin).
    const auto expectOnSurface = [&](const CollisionShapeStorage& s, const char* what) {
        double outside = -1.0, inside = 1.0;
        for (const auto& [a, b, c] : triangles(s))
            for (const Eigen::Vector3d& p : {a, b, c, Eigen::Vector3d((a + b + c) / 3.0)}) {
                outside = std::max(outside, signedDistance(p) + s.margin());
                inside = std::min(inside, signedDistance(p) + s.margin());
            }
        EXPECT_LT(outside, 0.2 * s.margin())
            << what << ": mesh + margin outside the torus by " << outside << " m";
        EXPECT_GT(inside, -0.35 * s.margin())
            << what << ": mesh + margin inside the torus by " << -inside << " m";
    };
    CollisionShapeOptions options;
    ASSERT_EQ(options.gimpactMaxTriangles, 1500);
    const auto coarse = buildCollisionShape(ring, CollisionShapeKind::GImpactMesh, options);
    const auto kept = triangles(*coarse);
    EXPECT_LE(kept.size(), static_cast<std::size_t>(options.gimpactMaxTriangles));
    EXPECT_GT(kept.size(), static_cast<std::size_t>(options.gimpactMaxTriangles / 2));
    expectOnSurface(*coarse, "budget 1,500");
    options.gimpactMaxTriangles = 0;
    const auto full = buildCollisionShape(ring, CollisionShapeKind::GImpactMesh, options);
    EXPECT_EQ(triangles(*full).size(), ring.triangles.size());
    expectOnSurface(*full, "every triangle");
    options.gimpactMaxTriangles = -1;
    try {
        buildCollisionShape(ring, CollisionShapeKind::GImpactMesh, options);
        ADD_FAILURE() << "a negative triangle budget was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("GImpact triangle budget -1"), std::string::npos) << e.what();
    }
}

// Bodies that can break keep their mesh surface above HACD's limit (their contact points are
// their fracture loads); those that cannot get convex pieces; convex meshes get a hull.
TEST(CollisionShapes, KindFollowsWhetherTheBodyCanBreak) {
    const TriangleMesh ring = makeTorus(0.1, 0.03, 32, 12);  // 768 triangles
    FractureBodySettings settings;
    EXPECT_EQ(collisionShapeKind(settings, ring), CollisionShapeKind::GImpactMesh);
    EXPECT_EQ(collisionShapeKind(settings, test::lShape(0.1, 0.02)), CollisionShapeKind::ConvexDecomposition);
    EXPECT_EQ(collisionShapeKind(settings, makeGeodesicSphere(0.1, 4)), CollisionShapeKind::ConvexHull);
    settings.refractureDepth = settings.maxRefractureDepth + 1;
    EXPECT_EQ(collisionShapeKind(settings, ring), CollisionShapeKind::ConvexDecomposition);
    settings.refractureDepth = 0;
    settings.fracturable = false;
    EXPECT_EQ(collisionShapeKind(settings, ring), CollisionShapeKind::ConvexDecomposition);
    settings.concaveShapeKind = CollisionShapeKind::GImpactMesh;
    EXPECT_EQ(collisionShapeKind(settings, ring), CollisionShapeKind::GImpactMesh);
}

TEST(CollisionShapes, NonConvexBodiesRestStablyOnTheGround) {
    for (const CollisionShapeKind kind :
         {CollisionShapeKind::ConvexDecomposition, CollisionShapeKind::GImpactMesh}) {
        btDefaultCollisionConfiguration config;
        btCollisionDispatcher dispatcher(&config);
        btDbvtBroadphase broadphase;
        btSequentialImpulseConstraintSolver solver;
        btFractureDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
        world.setGravity(btVector3(0, btScalar(-9.81), 0));
        btBoxShape groundShape(btVector3(5, btScalar(0.5), 5));
        btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
        btTransform t;
        t.setIdentity();
        t.setOrigin(btVector3(0, btScalar(-0.5), 0));
        ground.setWorldTransform(t);
        world.addRigidBody(&ground);
        FractureBodySettings settings;
        settings.fracturable = false;
        settings.concaveShapeKind = kind;
        // L lying flat (its z axis turned to world y), dropped from 5 cm.
        t.setRotation(btQuaternion(btVector3(1, 0, 0), btScalar(-M_PI / 2)));
        t.setOrigin(btVector3(0, btScalar(0.07), 0));
        btFractureRigidBody body(Material::glass(), test::lShape(0.1, 0.02), settings, t);
        world.addRigidBody(&body);
        for (int i = 0; i < 480; ++i) world.stepSimulation(btScalar(1.0 / 240.0), 1, btScalar(1.0 / 240.0));
        const double height = double(body.getWorldTransform().getOrigin().y());
        // Resting on its 4 cm thick side: centre of mass 2 cm above the ground, not a collision
        // margin (2.1 mm) higher: hulls and GImpact meshes lie a margin inside the surface.
        const double margin = double(body.getCollisionShape()->getMargin());
        EXPECT_NEAR(height, 0.02, 0.2 * margin) << toString(kind);
        EXPECT_LT(double(body.getLinearVelocity().length()), 1e-2) << toString(kind);
        world.removeRigidBody(&body);
        world.removeRigidBody(&ground);
    }
}

TEST(FragmentSeparation, OverlappingBoxesArePushedApartAboutTheirCentreOfMass) {
    const auto cube = makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 0.0, "cube").vertices;
    SeparationBody a{{ConvexPolytope{cube, 0.0}}, 1.0, 1.0, {}};
    SeparationBody b = a;
    for (auto& p : b.pieces[0].points) p.x() += 0.95;  // 5 cm overlap
    b.mass = 3.0;
    const SeparationResult r = separateOverlaps({a, b});
    ASSERT_EQ(r.pushes.size(), 2u);
    EXPECT_NEAR((r.pushes[1] - r.pushes[0]).x(), 0.05, 1e-6);
    // Mass-weighted: the common centre of mass stays.
    EXPECT_LT((1.0 * r.pushes[0] + 3.0 * r.pushes[1]).norm(), 1e-9);
    EXPECT_NEAR(r.largestPush, 0.0375, 1e-6);
    // Touching bodies are left alone.
    for (auto& p : b.pieces[0].points) p.x() += 0.05;
    const SeparationResult none = separateOverlaps({a, b});
    EXPECT_EQ(none.overlapsResolved, 0);
    EXPECT_EQ(none.largestPush, 0.0);
}

// Of a standing column's contact with the ground (normal +y, points at y = 0), its base fragment
// takes the contact over; a fragment 1 m up does not, so an overlap with the base below it is
// shared about their centre of mass instead of lifting the upper one alone (which added the
// potential energy of its whole push to the event). A GImpact fragment (no convex pieces) keeps it.
TEST(FragmentSeparation, FragmentsTakeOverOnlyTheStaticContactsTheyReach) {
    const StaticContact ground{Eigen::Vector3d(0, 1, 0),
                               {Eigen::Vector3d(-0.5, 0, 0), Eigen::Vector3d(0.5, 0, 0)}};
    auto boxAt = [](double y) {
        auto points = makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 0.0, "cube").vertices;
        for (auto& p : points) p.y() += y;
        return std::vector<ConvexPolytope>{ConvexPolytope{points, 0.0}};
    };
    EXPECT_EQ(blockedNormals({ground}, boxAt(0.5), 1.0).size(), 1u);   // resting on it
    EXPECT_EQ(blockedNormals({ground}, boxAt(0.54), 1.0).size(), 1u);  // 4 cm above: within 5 %
    EXPECT_TRUE(blockedNormals({ground}, boxAt(1.5), 1.0).empty());
    EXPECT_EQ(blockedNormals({ground}, {}, 1.0).size(), 1u);
    SeparationBody base{boxAt(0.5), 3.0, 1.0, blockedNormals({ground}, boxAt(0.5), 1.0)};
    SeparationBody upper{boxAt(1.4), 1.0, 1.0, blockedNormals({ground}, boxAt(1.4), 1.0)};
    const SeparationResult r = separateOverlaps({base, upper});
    EXPECT_EQ(r.pushes[0], Eigen::Vector3d::Zero());  // the base stays on the ground
    EXPECT_NEAR(r.pushes[1].y(), 0.1, 1e-6);
    SeparationBody middle{boxAt(2.3), 1.0, 1.0, blockedNormals({ground}, boxAt(2.3), 1.0)};
    const SeparationResult shared = separateOverlaps({upper, middle});
    EXPECT_LT((1.0 * shared.pushes[0] + 1.0 * shared.pushes[1]).norm(), 1e-9);  // centre of mass stays
}

// A fragment resting on static geometry is never pushed into it: the other one moves alone. This
// is what sank slab fragments into the ground (flat face on flat face: 3 cm below the plane).
TEST(FragmentSeparation, BodyOnStaticGeometryIsNotPushedIntoIt) {
    const auto cube = makeBox(Eigen::Vector3d(0.5, 0.5, 0.5), 0.0, "cube").vertices;
    SeparationBody below{{ConvexPolytope{cube, 0.0}}, 3.0, 1.0, {Eigen::Vector3d(0, 1, 0)}};  // on the ground
    SeparationBody above = below;
    above.mass = 1.0;
    above.blockedDirections.clear();
    for (auto& p : above.pieces[0].points) p.y() += 0.9;  // 10 cm overlap, the shallowest along y
    const SeparationResult r = separateOverlaps({below, above});
    EXPECT_EQ(r.pushes[0], Eigen::Vector3d::Zero());
    EXPECT_NEAR(r.pushes[1].y(), 0.1, 1e-6);
    EXPECT_NEAR(r.pushes[1].x(), 0.0, 1e-9);
    // Blocked on both sides: left to the solver.
    above.blockedDirections = {Eigen::Vector3d(0, -1, 0)};
    const SeparationResult stuck = separateOverlaps({below, above});
    EXPECT_EQ(stuck.largestPush, 0.0);
    EXPECT_NEAR(stuck.remainingDepth, 0.1, 1e-6);
}
