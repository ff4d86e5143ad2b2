// SPDX-License-Identifier: Zlib
#pragma once
// A Bullet rigid body that can break (paper §5). It is an ordinary btRigidBody for Bullet; in a
// btFractureDynamicsWorld its contacts are watched and, above its impulse threshold, handed to
// the world's FractureEngine.
//
// Body frame: origin at the centre of mass, axes along the principal axes of inertia (Bullet
// needs a diagonal local inertia). The closed triangle mesh, contacts and fragment specs are
// expressed in it. Constructors that take a model-frame mesh or shape compute volume, centre of
// mass and inertia (geometry/MassProperties.h, mass = volume * density) and place the body so
// that the model frame sits at `modelTransform`; bodyInModelFrame() tells where the body frame
// is inside the model frame.
//
// Ownership: the body owns its collision shape (CollisionShapeStorage) and its FractureState;
// it never owns a motion state.
#include <btFracture/core/Material.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/dynamics/CollisionShapeBuilder.h>
#include <btFracture/dynamics/FractureBodySettings.h>
#include <btFracture/dynamics/FractureState.h>

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

class btBoxShape;
class btConvexHullShape;

namespace btfracture {

class btFractureRigidBody : public btRigidBody {
public:
    // Closed, outward-oriented mesh in model coordinates [m] (checked with requireClosedSolid;
    // an inside-out mesh is flipped with a warning). The collision shape is a shrunk convex hull
    // when the mesh is convex, else settings.concaveShapeKind.
    btFractureRigidBody(const Material& material, TriangleMesh modelMesh,
                        const FractureBodySettings& settings = {},
                        const btTransform& modelTransform = btTransform::getIdentity());
    // A box: surface meshed with 12 triangles; body frame = box frame.
    btFractureRigidBody(const Material& material, const btBoxShape& box,
                        const FractureBodySettings& settings = {},
                        const btTransform& transform = btTransform::getIdentity());
    // A convex hull shape (local scaling applied): its hull is meshed with btConvexHullComputer.
    btFractureRigidBody(const Material& material, const btConvexHullShape& hull,
                        const FractureBodySettings& settings = {},
                        const btTransform& modelTransform = btTransform::getIdentity());
    // A mesh already in its body frame (centre of mass at the origin, principal axes), with its
    // shape, volume [m^3], principal moments [kg m^2] and the root body's volume (fragment classes,
    // §5.2). Used for fragments. Throws when the data are inconsistent, e.g. a volume above
    // originalVolume by more than kOriginalVolumeTolerance.
    btFractureRigidBody(const Material& material, TriangleMesh bodyFrameMesh,
                        std::unique_ptr<CollisionShapeStorage> shape, double volume,
                        const Eigen::Vector3d& principalInertia, double originalVolume,
                        const FractureBodySettings& settings, const btTransform& worldTransform);
    ~btFractureRigidBody() override;

    btFractureRigidBody(const btFractureRigidBody&) = delete;
    btFractureRigidBody& operator=(const btFractureRigidBody&) = delete;

    // nullptr unless `object` is a btFractureRigidBody (a tag test, no dynamic_cast: the body
    // marks itself through Bullet's extension pointer, reserved for Bullet extensions).
    static btFractureRigidBody* upcast(btCollisionObject* object) {
        return object && object->internalGetExtensionPointer() == object
                   ? static_cast<btFractureRigidBody*>(object)
                   : nullptr;
    }
    static const btFractureRigidBody* upcast(const btCollisionObject* object) {
        return upcast(const_cast<btCollisionObject*>(object));
    }

    // Fragments are named <root>_f<n>, n counting the fragments of that root in the order the
    // world made them (the runner's output names: FractureRecorder).
    const std::string& name() const { return mesh_.name; }
    // The name of the unbroken body this one broke from (its own name if it never broke).
    const std::string& rootName() const { return rootName_.empty() ? mesh_.name : rootName_; }
    const Material& material() const { return material_; }
    const TriangleMesh& mesh() const { return mesh_; }  // body frame [m]
    const FractureBodySettings& settings() const { return settings_; }
    // Changing settings is allowed between steps; they are validated here.
    void setSettings(const FractureBodySettings& settings);
    // fracturable and not deeper than maxRefractureDepth
    bool isFracturable() const {
        return settings_.fracturable && settings_.refractureDepth <= settings_.maxRefractureDepth;
    }

    double volume() const { return volume_; }                  // [m^3]
    double originalVolume() const { return originalVolume_; }  // volume of the unbroken root body [m^3]
    // Relative amount by which a fragment's volume may exceed originalVolume(): fragment volumes
    // are measured on the level set, the root's on its mesh (< 0.5 % apart at default voxels).
    static constexpr double kOriginalVolumeTolerance = 0.02;
    double characteristicLength() const { return characteristicLength_; }  // cube root of the volume [m]
    const btTransform& bodyInModelFrame() const { return bodyInModelFrame_; }
    const CollisionShapeStorage& shapeStorage() const { return *shape_; }
    // Rebuilds the collision shape from new convex pieces (CollisionShapeStorage::replacePieces),
    // before the body enters a world (throws btfracture::Error naming the body otherwise).
    void replaceConvexPieces(std::vector<ConvexPolytope> bodyFramePieces);

    // Mean curvature of the mesh at the surface point nearest to `bodyPoint` [1/m]
    // (ContactCurvature.h).
    double meanCurvatureAt(const Eigen::Vector3d& bodyPoint) const;

    // The engine's lazily built state (BEM solver, level set, cracks); nullptr until then.
    FractureState* fractureState() const { return state_.get(); }
    void setFractureState(std::unique_ptr<FractureState> state) { state_ = std::move(state); }
    std::unique_ptr<FractureState> releaseFractureState() { return std::move(state_); }

    // The pad of this body's broadphase box [m] as btFractureDynamicsWorld set it with the box
    // (dynamics/ContactPad); 0 until it does (the box Bullet makes when a body is added has
    // none). Never more than the box's pad.
    btScalar broadphasePad() const { return broadphasePad_; }

private:
    friend class btFractureDynamicsWorld;
    struct Prepared;
    btFractureRigidBody(Prepared prepared, const Material& material, const FractureBodySettings& settings);
    static Prepared prepareModelMesh(TriangleMesh mesh, const Material& material,
                                     const FractureBodySettings& settings, const btTransform& modelTransform);
    static btRigidBodyConstructionInfo constructionInfo(const Prepared& prepared, const Material& material);

    Material material_;
    TriangleMesh mesh_;
    FractureBodySettings settings_;
    std::unique_ptr<CollisionShapeStorage> shape_;
    std::unique_ptr<FractureState> state_;
    double volume_ = 0.0;
    double originalVolume_ = 0.0;
    std::string rootName_;  // set by btFractureDynamicsWorld for fragments
    double characteristicLength_ = 0.0;
    btTransform bodyInModelFrame_;
    std::vector<double> vertexCurvature_;

    // Scratch of btFractureDynamicsWorld's step hook (no allocation per step).
    std::uint64_t hookStamp_ = 0;   // step in which impulseSum_ was last reset
    double impulseSum_ = 0.0;       // summed normal impulse of that step [N s]
    bool inFractureWorld_ = false;  // counted by a btFractureDynamicsWorld
    btScalar broadphasePad_ = 0;    // pad of the box last set (ContactPad) [m]
};

}  // namespace btfracture
