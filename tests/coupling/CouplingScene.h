// SPDX-License-Identifier: Zlib
#pragma once
// Test scenes for the Bullet coupling: a ground box, a fracturable glass slab resting on it and
// a steel ball thrown down at it, in a btFractureDynamicsWorld with the plane-split engine (or
// the physical BemFractureEngine).
#include <btFracture/core/Material.h>
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/dynamics/PlaneSplitFractureEngine.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <btBulletDynamicsCommon.h>

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstring>
#include <memory>
#include <vector>

namespace btfracture::test {

constexpr double kStep = 1.0 / 240.0;

struct SceneOptions {
    double impulseThreshold = 10.0;     // [N s]
    double ballSpeed = 10.0;            // [m/s], downwards
    double ballX = 0.05, ballZ = 0.03;  // where the ball hits the slab's top face [m]
    int maxRefractureDepth = 2;
    int bemTriangleTarget = FractureBodySettings().bemTriangleTarget;  // the slab's BEM resolution
    bool withEngine = true;
    bool physicalEngine = false;  // BemFractureEngine instead of the plane-split stand-in
    bool surfaceSeeds = false;    // its CrackSettings::surfaceSeeds
    Eigen::Vector3d slabHalfExtents = Eigen::Vector3d(0.2, 0.025, 0.2);  // [m]
    // Free flight: no gravity, the slab lifted 0.5 m off the ground, moving and spinning.
    bool freeFlight = false;
    Eigen::Vector3d slabVelocity = Eigen::Vector3d::Zero();         // [m/s]
    Eigen::Vector3d slabAngularVelocity = Eigen::Vector3d::Zero();  // [rad/s]
};

// Momentum, energy and mass of the dynamic rigid bodies in a world (double precision).
struct WorldProbe {
    double mass = 0.0;
    Eigen::Vector3d linear = Eigen::Vector3d::Zero();
    Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // about the world origin
    double kinetic = 0.0;
    int bodies = 0;
};

inline Eigen::Vector3d eig(const btVector3& v) {
    return Eigen::Vector3d(double(v.x()), double(v.y()), double(v.z()));
}

inline WorldProbe probe(btDiscreteDynamicsWorld& world) {
    WorldProbe p;
    for (int i = 0; i < world.getNumCollisionObjects(); ++i) {
        const btRigidBody* body = btRigidBody::upcast(world.getCollisionObjectArray()[i]);
        if (!body || body->getInvMass() == 0) continue;
        const double m = 1.0 / double(body->getInvMass());
        const Eigen::Vector3d x = eig(body->getWorldTransform().getOrigin());
        const Eigen::Vector3d v = eig(body->getLinearVelocity());
        const Eigen::Vector3d w = eig(body->getAngularVelocity());
        Eigen::Matrix3d R;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) R(r, c) = double(body->getWorldTransform().getBasis()[r][c]);
        const Eigen::Vector3d invI = eig(body->getInvInertiaDiagLocal());
        const Eigen::Matrix3d I = R * invI.cwiseInverse().asDiagonal() * R.transpose();
        p.mass += m;
        p.linear += m * v;
        p.angular += I * w + m * x.cross(v);
        p.kinetic += 0.5 * m * v.squaredNorm() + 0.5 * w.dot(I * w);
        ++p.bodies;
    }
    return p;
}

class Scene {
public:
    explicit Scene(const SceneOptions& options = {}) {
        world = std::make_unique<btFractureDynamicsWorld>(&dispatcher, &broadphase, &solver, &config);
        world->setGravity(btVector3(0, options.freeFlight ? btScalar(0) : btScalar(-9.81), 0));
        const double lift = options.freeFlight ? 0.5 : 0.0;
        if (options.withEngine && options.physicalEngine) {
            BemFractureEngineSettings engine;
            engine.fracture.surfaceSeeds = options.surfaceSeeds;
            world->setFractureEngine(std::make_unique<BemFractureEngine>(engine));
        } else if (options.withEngine)
            world->setFractureEngine(std::make_unique<PlaneSplitFractureEngine>());

        btTransform t;
        t.setIdentity();
        t.setOrigin(btVector3(0, btScalar(-0.5), 0));
        ground =
            std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
        ground->setWorldTransform(t);
        world->addRigidBody(ground.get());

        FractureBodySettings settings;
        settings.impulseThreshold = options.impulseThreshold;
        settings.maxRefractureDepth = options.maxRefractureDepth;
        settings.bemTriangleTarget = options.bemTriangleTarget;
        const btBoxShape slabShape(btVector3(btScalar(options.slabHalfExtents.x()),
                                             btScalar(options.slabHalfExtents.y()),
                                             btScalar(options.slabHalfExtents.z())));
        t.setOrigin(btVector3(0, btScalar(options.slabHalfExtents.y() + lift), 0));
        slab = std::make_unique<btFractureRigidBody>(Material::glass(), slabShape, settings, t);
        slab->setLinearVelocity(btVector3(btScalar(options.slabVelocity.x()),
                                          btScalar(options.slabVelocity.y()),
                                          btScalar(options.slabVelocity.z())));
        slab->setAngularVelocity(btVector3(btScalar(options.slabAngularVelocity.x()),
                                           btScalar(options.slabAngularVelocity.y()),
                                           btScalar(options.slabAngularVelocity.z())));
        slab->setFriction(btScalar(0.6));
        world->addRigidBody(slab.get());

        const btScalar radius = ballShape.getRadius();
        const btScalar mass = btScalar(7850.0 * 4.0 / 3.0 * M_PI * double(radius * radius * radius));
        btVector3 inertia;
        ballShape.calculateLocalInertia(mass, inertia);
        ball = std::make_unique<btRigidBody>(
            btRigidBody::btRigidBodyConstructionInfo(mass, nullptr, &ballShape, inertia));
        t.setOrigin(btVector3(btScalar(options.ballX),
                              btScalar(2.0 * options.slabHalfExtents.y() + lift + 0.05 + 0.03),
                              btScalar(options.ballZ)));
        ball->setWorldTransform(t);
        ball->setLinearVelocity(btVector3(0, btScalar(-options.ballSpeed), 0));
        world->addRigidBody(ball.get());
    }

    ~Scene() {
        // App-added bodies leave the world before it goes; world-owned fragments go with it.
        for (btRigidBody* body :
             {static_cast<btRigidBody*>(ball.get()), static_cast<btRigidBody*>(slab.get()), ground.get()})
            if (body && body->isInWorld()) world->removeRigidBody(body);
        world.reset();
    }

    void step(int count = 1) {
        for (int i = 0; i < count; ++i) world->stepSimulation(btScalar(kStep), 1, btScalar(kStep));
    }

    // Poses of the fragments, in world array order.
    std::vector<btTransform> fragmentPoses() const {
        std::vector<btTransform> poses;
        for (btFractureRigidBody* f : fragments()) poses.push_back(f->getWorldTransform());
        return poses;
    }

    // Fragments in the world (world-owned btFractureRigidBody), in world array order.
    std::vector<btFractureRigidBody*> fragments() const {
        std::vector<btFractureRigidBody*> out;
        for (int i = 0; i < world->getNumCollisionObjects(); ++i) {
            btCollisionObject* object = world->getCollisionObjectArray()[i];
            if (world->ownsBody(object)) out.push_back(btFractureRigidBody::upcast(object));
        }
        return out;
    }

    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btBoxShape groundShape{btVector3(5, btScalar(0.5), 5)};
    btSphereShape ballShape{btScalar(0.05)};
    std::unique_ptr<btFractureDynamicsWorld> world;
    std::unique_ptr<btRigidBody> ground;
    std::unique_ptr<btFractureRigidBody> slab;
    std::unique_ptr<btRigidBody> ball;
};

// Two runs' fragment poses agree bit for bit.
inline void expectBitIdentical(const std::vector<btTransform>& first,
                               const std::vector<btTransform>& second) {
    ASSERT_GE(first.size(), 2u);
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(std::memcmp(&first[i].getBasis(), &second[i].getBasis(), sizeof(btMatrix3x3)), 0) << i;
        EXPECT_EQ(std::memcmp(&first[i].getOrigin(), &second[i].getOrigin(), sizeof(btVector3)), 0) << i;
    }
}

}  // namespace btfracture::test
