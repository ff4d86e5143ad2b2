// SPDX-License-Identifier: Zlib
#include <btFracture/io/FractureSceneWorldFactory.h>

#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/dynamics/btFractureDynamicsWorld.h>
#include <btFracture/dynamics/btFractureRigidBody.h>

#include <cmath>

namespace btfracture {

std::uint64_t combineSeeds(std::uint64_t runSeed, std::uint64_t bodySeed) {
    std::uint64_t z = runSeed * 0x9E3779B97F4A7C15ULL + bodySeed + 0x632BE59BD9B4E019ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

FractureSceneWorldFactory::FractureSceneWorldFactory(std::uint64_t runSeed,
                                                     const BemFractureEngineSettings& engine)
    : runSeed_(runSeed), engine_(engine) {}

std::unique_ptr<btDiscreteDynamicsWorld> FractureSceneWorldFactory::createWorld(
    btCollisionDispatcher& dispatcher, btBroadphaseInterface& broadphase, btConstraintSolver& solver,
    btCollisionConfiguration& configuration, const Scene& scene) const {
    auto world = std::make_unique<btFractureDynamicsWorld>(&dispatcher, &broadphase, &solver, &configuration);
    BemFractureEngineSettings settings = engine_;
    settings.voxelFronts = scene.effects.voxelFronts;
    settings.idleMatrixBudgetMB = scene.effects.idleMatrixBudgetMB;
    settings.fracture.surfaceSeeds = scene.effects.surfaceSeeds;
    settings.fracture.estimatorSurfaceFronts = scene.effects.estimatorSurfaceFronts;
    auto engine = std::make_unique<BemFractureEngine>(settings);
    if (cutObserver_) engine->setCutObserver(cutObserver_);
    world->setFractureEngine(std::move(engine));
    world->setFragmentSleeping(scene.effects.fragmentSleeping);
    return world;
}

std::unique_ptr<btRigidBody> FractureSceneWorldFactory::createBody(
    const btRigidBody::btRigidBodyConstructionInfo& info, const SceneBody& description,
    const TriangleMesh& surface) const {
    if (!description.fracture.fracturable) return SceneWorldFactory::createBody(info, description, surface);
    if (description.isStatic() || description.motion == SceneMotion::Kinematic || !(info.m_mass > 0)) {
        logf(LogLevel::Warning, "body '", description.name, "' is ",
             description.motion == SceneMotion::Kinematic ? "kinematic" : "static",
             " and cannot break (fragments need a mass); it stays rigid");
        return SceneWorldFactory::createBody(info, description, surface);
    }
    const double volume = computeMassProperties(surface).volume;
    const Material& m = description.material;
    const double density = static_cast<double>(info.m_mass) / volume;
    Material material = m;
    if (std::abs(density - m.density()) > 1e-9 * m.density())
        material = Material(m.youngsModulus(), m.poissonRatio(), density, m.tensileStrength(),
                            m.fractureToughness(), m.compressiveFactor(), m.name());
    FractureBodySettings settings = description.fracture;
    settings.materialNoise.seed = combineSeeds(runSeed_, settings.materialNoise.seed);
    // The scene's mesh collision choice holds for the body and its non-convex fragments.
    if (description.shape.type == SceneShapeType::Mesh)
        settings.concaveShapeKind = description.shape.collision == SceneMeshCollision::GImpact
                                        ? CollisionShapeKind::GImpactMesh
                                        : CollisionShapeKind::ConvexHull;
    TriangleMesh mesh = surface;
    mesh.name = description.name;
    // `surface` is already in the body frame SceneWorld chose, so the model frame sits at the
    // start transform; btFractureRigidBody re-derives the centre of mass and principal axes.
    return std::make_unique<btFractureRigidBody>(material, std::move(mesh), settings,
                                                 info.m_startWorldTransform);
}

}  // namespace btfracture
