// SPDX-License-Identifier: Zlib
#pragma once
// Builds a scene's world so that its breakable bodies break (paper §5): a btFractureDynamicsWorld
// with the physical BemFractureEngine, a btFractureRigidBody for every dynamic body that the
// scene's effects.fracture marks breakable, and a plain btRigidBody for everything else (which
// then costs nothing extra, issue "effects only where called for").
//
// Mass: a breakable body's density is the scene's (mass / volume when the scene gives a mass),
// so that fragments carry the same density. Static and kinematic bodies cannot break (their
// fragments would have no mass to inherit): they stay rigid, with a warning.
// Material noise: a body's noise seed is combined with the run seed (effects.seed / --seed).
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/io/SceneWorld.h>

#include <cstdint>

namespace btfracture {

class FractureSceneWorldFactory : public SceneWorldFactory {
public:
    // The engine's crack cut (voxelFronts) comes from each scene's effects.crack_cut.
    explicit FractureSceneWorldFactory(std::uint64_t runSeed, const BemFractureEngineSettings& engine = {});

    // The engine's cut observer (BemFractureEngine::setCutObserver), installed on the world's engine.
    void setCutObserver(BemFractureEngine::CutObserver observer) { cutObserver_ = std::move(observer); }

    std::unique_ptr<btDiscreteDynamicsWorld> createWorld(btCollisionDispatcher& dispatcher,
                                                         btBroadphaseInterface& broadphase,
                                                         btConstraintSolver& solver,
                                                         btCollisionConfiguration& configuration,
                                                         const Scene& scene) const override;
    std::unique_ptr<btRigidBody> createBody(const btRigidBody::btRigidBodyConstructionInfo& info,
                                            const SceneBody& description,
                                            const TriangleMesh& surface) const override;

private:
    std::uint64_t runSeed_;
    BemFractureEngineSettings engine_;
    BemFractureEngine::CutObserver cutObserver_;
};

// The seed a body's material noise uses in a run: a fixed mix of both (splitmix64), so that
// different bodies and different run seeds give independent realisations.
std::uint64_t combineSeeds(std::uint64_t runSeed, std::uint64_t bodySeed);

}  // namespace btfracture
