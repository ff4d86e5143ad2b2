// SPDX-License-Identifier: Zlib
#pragma once
// A Bullet world built from a Scene (io/SceneFile.h): rigid bodies only, in a
// btDiscreteDynamicsWorld with btSequentialImpulseConstraintSolver.
//
// Body frames: a body's frame is at its centre of mass along its principal axes (what Bullet
// expects). Meshes are scaled, their mass properties computed exactly (core/MassProperties.h),
// and their vertices re-expressed in that frame; boxes and spheres are already centred. Each body
// keeps its closed surface mesh in the body frame for output (planes: a 20 m x 20 m display
// square).
//
// Mesh collision: SceneMeshCollision::ConvexHull gives a btConvexHullShape of the hull shrunk by
// the collision margin (so hull + margin matches the mesh instead of bulging out by one margin);
// GImpact gives a btGImpactMeshShape over all triangles, with btGImpactCollisionAlgorithm
// registered on the dispatcher. Margin: min(0.04 m, 0.02 * cube root of the body volume).
//
// Motion: a "sleeping" body starts deactivated (ISLAND_SLEEPING) until something touches it; a
// "kinematic" body (CF_KINEMATIC_OBJECT, infinite mass) is moved by stepFrame at its constant
// linear and angular velocity before each Bullet step. Friction and restitution come from the
// scene.
//
// Extension point: SceneWorldFactory is the one place where the world and the bodies are
// created; FractureSceneWorldFactory (io/FractureSceneWorldFactory.h) builds btFracture's own
// btFractureDynamicsWorld / btFractureRigidBody from the same scene. SceneWorld owns everything
// it creates; a btFractureRigidBody's surface and volume are its own (body frame).
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/io/SceneFile.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

class btBroadphaseInterface;
class btCollisionConfiguration;
class btCollisionDispatcher;
class btConstraintSolver;
class btDiscreteDynamicsWorld;

namespace btfracture {

class btFractureRigidBody;

class SceneWorldFactory {
public:
    virtual ~SceneWorldFactory() = default;
    // The world over Bullet's parts, which SceneWorld owns and keeps alive longer than the world.
    virtual std::unique_ptr<btDiscreteDynamicsWorld> createWorld(btCollisionDispatcher& dispatcher,
                                                                 btBroadphaseInterface& broadphase,
                                                                 btConstraintSolver& solver,
                                                                 btCollisionConfiguration& configuration,
                                                                 const Scene& scene) const;
    // One body. `info` carries the shape, mass, principal inertia and start transform (centre of
    // mass frame); `surface` is the body's closed surface mesh in that frame (a display square for
    // planes); `description` has the material, resolutions and fracture settings
    // (description.fracture: dynamics' FractureBodySettings, fracturable or not). SceneWorld sets the
    // velocities, friction, restitution and motion state and adds the body to the world afterwards.
    virtual std::unique_ptr<btRigidBody> createBody(const btRigidBody::btRigidBodyConstructionInfo& info,
                                                    const SceneBody& description,
                                                    const TriangleMesh& surface) const;
};

class SceneWorld {
public:
    // Loads every mesh (readMesh: validated, closed) and builds the world. Throws
    // btfracture::Error naming the scene file and the body when a mesh cannot be used.
    explicit SceneWorld(const Scene& scene, const SceneWorldFactory& factory = SceneWorldFactory());
    ~SceneWorld();
    SceneWorld(const SceneWorld&) = delete;
    SceneWorld& operator=(const SceneWorld&) = delete;

    btDiscreteDynamicsWorld& world();
    const Scene& scene() const;

    // Advances one frame: scene.world.substeps fixed Bullet steps of dt / substeps each.
    void stepFrame();
    int framesTaken() const;
    double time() const;  // simulated time [s]

    struct Body {
        std::string name;
        btRigidBody* rigidBody = nullptr;  // owned by SceneWorld
        TriangleMesh surface;              // body frame (centre of mass, principal axes)
        double volume = 0.0;               // [m^3]; 0 for planes
        bool plane = false;                // an infinite plane (its surface is a display square)
        std::string parent;                // the body it broke off; empty for scene bodies
        std::vector<bool> crackFaces;      // per surface triangle: made by a cut (io/CrackFaces.h)
    };
    const std::vector<Body>& bodies() const;
    // The first body (in bodies() order) whose position, orientation or velocity is NaN or Inf;
    // nullptr while every state is finite.
    const Body* firstNonFiniteBody() const;
    // Body `index`'s surface at its current pose, in world coordinates.
    TriangleMesh worldSurface(size_t index) const;

    // A body that broke and left the world, with its state at that moment.
    struct Removal {
        std::string name;
        btTransform pose;
        btVector3 linearVelocity, angularVelocity;
    };
    // Every removal so far, in order.
    const std::vector<Removal>& removals() const;

    // Fracture (call from a FractureListener): `parent` left the world and `fragments` took its
    // place; their entries replace the parent's, in the given order, with the given output names
    // and their collision-resolution surfaces. A parent SceneWorld created is deleted at the
    // start of the next frame (the world's ownership rule: the application deletes it after the
    // listeners ran). Throws btfracture::Error if `parent` is not one of bodies().
    void replaceBody(const btRigidBody& parent,
                     const std::vector<std::pair<btFractureRigidBody*, std::string>>& fragments);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace btfracture
