// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/dynamics/BulletEigen.h>
#include <btFracture/dynamics/ContactCurvature.h>
#include <btFracture/geometry/ConvexHull.h>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <cmath>
#include <sstream>

namespace btfracture {

struct btFractureRigidBody::Prepared {
    TriangleMesh mesh;  // body frame
    std::unique_ptr<CollisionShapeStorage> shape;
    double volume = 0.0;
    Eigen::Vector3d principalInertia = Eigen::Vector3d::Zero();
    double originalVolume = 0.0;
    btTransform worldTransform;
    btTransform bodyInModelFrame;
};

namespace {

std::string nameOr(const std::string& name, const char* fallback) {
    return name.empty() ? std::string(fallback) : name;
}

TriangleMesh hullMeshOf(const btConvexHullShape& hull) {
    std::vector<Eigen::Vector3d> points;
    const btVector3 scaling = hull.getLocalScaling();
    for (int i = 0; i < hull.getNumPoints(); ++i)
        points.push_back(toEigen(hull.getUnscaledPoints()[i] * scaling));
    return convexHullMesh(points, "btConvexHullShape");
}

}  // namespace

btRigidBody::btRigidBodyConstructionInfo btFractureRigidBody::constructionInfo(const Prepared& p,
                                                                               const Material& material) {
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(p.volume * material.density()), nullptr,
                                                  p.shape->shape(), toBullet(p.principalInertia));
    info.m_startWorldTransform = p.worldTransform;
    return info;
}

btFractureRigidBody::Prepared btFractureRigidBody::prepareModelMesh(TriangleMesh mesh,
                                                                    const Material& material,
                                                                    const FractureBodySettings& settings,
                                                                    const btTransform& modelTransform) {
    mesh.name = nameOr(mesh.name, "btFractureRigidBody");
    validate(settings, mesh.name);
    requireClosedSolid(mesh);
    const MassProperties mp = computeMassProperties(mesh);
    const PrincipalAxes axes = principalAxes(mp.inertiaPerDensity);

    Prepared p;
    // x_body = R^T (x_model - c)
    for (auto& v : mesh.vertices) v = axes.rotation.transpose() * (v - mp.centreOfMass);
    p.volume = mp.volume;
    p.originalVolume = mp.volume;
    p.principalInertia = material.density() * axes.moments;
    p.bodyInModelFrame = toBullet(axes.rotation, mp.centreOfMass);
    p.worldTransform = modelTransform * p.bodyInModelFrame;
    p.shape = buildCollisionShape(mesh, collisionShapeKind(settings, mesh), settings.shapeOptions);
    p.mesh = std::move(mesh);
    return p;
}

btFractureRigidBody::btFractureRigidBody(Prepared p, const Material& material,
                                         const FractureBodySettings& settings)
    : btRigidBody(constructionInfo(p, material)),
      material_(material),
      mesh_(std::move(p.mesh)),
      settings_(settings),
      shape_(std::move(p.shape)),
      volume_(p.volume),
      originalVolume_(p.originalVolume),
      characteristicLength_(std::cbrt(p.volume)),
      bodyInModelFrame_(p.bodyInModelFrame),
      vertexCurvature_(vertexMeanCurvature(mesh_)) {
    validate(settings_, mesh_.name);
    internalSetExtensionPointer(static_cast<btCollisionObject*>(this));
}

btFractureRigidBody::btFractureRigidBody(const Material& material, TriangleMesh modelMesh,
                                         const FractureBodySettings& settings,
                                         const btTransform& modelTransform)
    : btFractureRigidBody(prepareModelMesh(std::move(modelMesh), material, settings, modelTransform),
                          material, settings) {}

btFractureRigidBody::btFractureRigidBody(const Material& material, const btBoxShape& box,
                                         const FractureBodySettings& settings, const btTransform& transform)
    : btFractureRigidBody(material, makeBox(toEigen(box.getHalfExtentsWithMargin()), 0.0, "box"), settings,
                          transform) {}

btFractureRigidBody::btFractureRigidBody(const Material& material, const btConvexHullShape& hull,
                                         const FractureBodySettings& settings,
                                         const btTransform& modelTransform)
    : btFractureRigidBody(material, hullMeshOf(hull), settings, modelTransform) {}

btFractureRigidBody::btFractureRigidBody(const Material& material, TriangleMesh bodyFrameMesh,
                                         std::unique_ptr<CollisionShapeStorage> shape, double volume,
                                         const Eigen::Vector3d& principalInertia, double originalVolume,
                                         const FractureBodySettings& settings,
                                         const btTransform& worldTransform)
    : btFractureRigidBody(
          [&]() {
              const std::string name = nameOr(bodyFrameMesh.name, "btFractureRigidBody fragment");
              std::ostringstream problem;
              if (!shape)
                  problem << "no collision shape";
              else if (!(volume > 0.0) || !std::isfinite(volume))
                  problem << "volume " << volume << " m^3 (need > 0)";
              else if (!principalInertia.allFinite() || !(principalInertia.minCoeff() > 0.0))
                  problem << "principal inertia (" << principalInertia.transpose() << ") kg m^2 (need > 0)";
              else if (!(originalVolume >= volume * (1.0 - kOriginalVolumeTolerance)) ||
                       !std::isfinite(originalVolume))
                  problem << "original volume " << originalVolume << " m^3 below the body's volume "
                          << volume;
              if (problem.tellp() > 0) throw Error(name + ": " + problem.str());
              Prepared p;
              p.mesh = std::move(bodyFrameMesh);
              p.mesh.name = name;
              p.shape = std::move(shape);
              p.volume = volume;
              p.principalInertia = principalInertia;
              p.originalVolume = originalVolume;
              p.worldTransform = worldTransform;
              p.bodyInModelFrame.setIdentity();
              return p;
          }(),
          material, settings) {}

btFractureRigidBody::~btFractureRigidBody() = default;

void btFractureRigidBody::setSettings(const FractureBodySettings& settings) {
    validate(settings, mesh_.name);
    settings_ = settings;
}

double btFractureRigidBody::meanCurvatureAt(const Eigen::Vector3d& bodyPoint) const {
    return btfracture::meanCurvatureAt(mesh_, vertexCurvature_, bodyPoint);
}

void btFractureRigidBody::replaceConvexPieces(std::vector<ConvexPolytope> bodyFramePieces) {
    if (isInWorld()) throw Error(name() + ": collision shape pieces can only be replaced outside a world");
    shape_->replacePieces(std::move(bodyFramePieces));
    setCollisionShape(shape_->shape());
}

}  // namespace btfracture
