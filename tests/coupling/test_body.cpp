// SPDX-License-Identifier: Zlib
#include "TestMeshes.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/ConvexHull.h>

#include <btBulletDynamicsCommon.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace btfracture;

namespace {

Eigen::Vector3d eig(const btVector3& v) {
    return Eigen::Vector3d(double(v.x()), double(v.y()), double(v.z()));
}

}  // namespace

TEST(FractureBody, BoxHasExactMassAndInertia) {
    const btBoxShape box(btVector3(btScalar(0.2), btScalar(0.05), btScalar(0.1)));
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(1, 2, 3));
    btFractureRigidBody body(Material::glass(), box, {}, t);
    const double volume = 0.4 * 0.1 * 0.2, mass = 2500.0 * volume;
    EXPECT_NEAR(body.volume(), volume, 1e-6 * volume);  // float half extents in a float build
    EXPECT_NEAR(1.0 / double(body.getInvMass()), mass, 1e-5 * mass);
    // Principal moments m/12 (b^2 + c^2), ascending order in the body frame.
    const Eigen::Vector3d expected =
        mass / 12.0 * Eigen::Vector3d(0.4 * 0.4 + 0.1 * 0.1, 0.4 * 0.4 + 0.2 * 0.2, 0.1 * 0.1 + 0.2 * 0.2);
    Eigen::Vector3d sorted = expected;
    std::sort(sorted.data(), sorted.data() + 3);
    EXPECT_LT((eig(body.getInvInertiaDiagLocal()).cwiseInverse() - sorted).norm(), 1e-5 * sorted.norm());
    EXPECT_LT((eig(body.getWorldTransform().getOrigin()) - Eigen::Vector3d(1, 2, 3)).norm(), 1e-6);
    EXPECT_EQ(btFractureRigidBody::upcast(&body), &body);
    EXPECT_TRUE(body.isFracturable());
    EXPECT_EQ(body.shapeStorage().kind(), CollisionShapeKind::ConvexHull);
    // The body's mesh is centred at its centre of mass.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& v : body.mesh().vertices) sum += v;
    EXPECT_LT(sum.norm(), 1e-12);
}

TEST(FractureBody, OffsetMeshIsRecentredAndPlaced) {
    TriangleMesh mesh = test::lShape(0.1, 0.02);  // non-convex, centre of mass off the origin
    btTransform model;
    model.setIdentity();
    model.setOrigin(btVector3(0, 1, 0));
    btFractureRigidBody body(Material::pmma(), mesh, {}, model);
    EXPECT_EQ(body.shapeStorage().kind(), CollisionShapeKind::ConvexDecomposition);
    EXPECT_GE(body.shapeStorage().convexPieces().size(), 2u);
    // L of three 0.1 squares: centroid (2a/3 ... ) = (5/6 a, 5/6 a) by symmetry of the L.
    const Eigen::Vector3d com(5.0 / 6.0 * 0.1, 5.0 / 6.0 * 0.1, 0.0);
    EXPECT_LT((eig(body.bodyInModelFrame().getOrigin()) - com).norm(), 1e-7);
    EXPECT_LT((eig(body.getWorldTransform().getOrigin()) - (com + Eigen::Vector3d(0, 1, 0))).norm(), 1e-6);
    // Mapping the body mesh back to the model frame gives the input mesh.
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Eigen::Vector3d back =
            eig(body.bodyInModelFrame() * btVector3(btScalar(body.mesh().vertices[i].x()),
                                                    btScalar(body.mesh().vertices[i].y()),
                                                    btScalar(body.mesh().vertices[i].z())));
        EXPECT_LT((back - mesh.vertices[i]).norm(), 1e-6);
    }
}

TEST(FractureBody, ConvexHullShapeIsMeshed) {
    btConvexHullShape hull;
    for (const auto& v : makeBox(Eigen::Vector3d(0.1, 0.2, 0.3), 0.0, "b").vertices)
        hull.addPoint(btVector3(btScalar(v.x() + 0.5), btScalar(v.y()), btScalar(v.z())));
    btFractureRigidBody body(Material::concrete(), hull);
    EXPECT_NEAR(body.volume(), 0.2 * 0.4 * 0.6, 1e-8);
    EXPECT_NEAR(double(body.bodyInModelFrame().getOrigin().x()), 0.5, 1e-6);
}

TEST(FractureBody, CurvatureProxy) {
    // A finely meshed sphere reads as radius r; a flat face of a large box as (nearly) flat.
    TriangleMesh sphere;
    {
        const int rings = 24, segments = 48;
        const double r = 0.05;
        sphere.vertices.push_back({0, 0, r});
        for (int i = 1; i < rings; ++i)
            for (int j = 0; j < segments; ++j) {
                const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
                sphere.vertices.push_back(
                    {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)});
            }
        sphere.vertices.push_back({0, 0, -r});
        const int south = static_cast<int>(sphere.vertices.size()) - 1;
        auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + j % segments; };
        for (int j = 0; j < segments; ++j) sphere.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < rings; ++i)
            for (int j = 0; j < segments; ++j) {
                sphere.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
                sphere.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
            }
        for (int j = 0; j < segments; ++j)
            sphere.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
        sphere.name = "sphere";
    }
    btFractureRigidBody ball(Material::glass(), sphere);
    EXPECT_NEAR(ball.meanCurvatureAt(Eigen::Vector3d(0.06, 0.0, 0.01)), 1.0 / 0.05, 0.03 / 0.05);
    // Torus (R 0.3, r 0.1): mean curvature (1/r + cos v/(R + r cos v))/2 is 2.5 1/m on the inner
    // equator (saddle) and 6.25 1/m on the outer one.
    FractureBodySettings settings;
    settings.concaveShapeKind = CollisionShapeKind::GImpactMesh;  // no decomposition needed here
    btFractureRigidBody ring(Material::glass(), makeTorus(0.3, 0.1, 96, 32), settings);
    const btTransform toBody = ring.bodyInModelFrame().inverse();
    const Eigen::Vector3d innerPoint = eig(toBody * btVector3(btScalar(0.2), 0, 0));
    const Eigen::Vector3d outerPoint = eig(toBody * btVector3(btScalar(0.4), 0, 0));
    EXPECT_NEAR(ring.meanCurvatureAt(innerPoint), 2.5, 0.25);
    EXPECT_NEAR(ring.meanCurvatureAt(outerPoint), 6.25, 0.4);
}

TEST(FractureBody, BadInputThrowsNamingTheBody) {
    TriangleMesh open = makeBox(Eigen::Vector3d(1, 1, 1), 0.0, "open box");
    open.triangles.pop_back();
    try {
        btFractureRigidBody body(Material::glass(), open);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("open box"), std::string::npos) << e.what();
    }
    FractureBodySettings settings;
    settings.impulseThreshold = -1.0;
    try {
        btFractureRigidBody body(Material::glass(), makeBox(Eigen::Vector3d(1, 1, 1), 0.0, "cube"), settings);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("impulseThreshold -1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cube"), std::string::npos) << e.what();
    }
    btRigidBody plain(btRigidBody::btRigidBodyConstructionInfo(1, nullptr, nullptr));
    EXPECT_EQ(btFractureRigidBody::upcast(&plain), nullptr);
}
