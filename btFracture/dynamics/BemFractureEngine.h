// SPDX-License-Identifier: Zlib
#pragma once
// The physical fracture engine (paper §3-§5): contact impulses -> Hertz tractions balanced by
// Eq. 6 -> the body's prefactored BEM (built on first need at the body's BEM resolution) ->
// FractureSolver (initiation, FULL / EST / HYBRID propagation) -> the crack sheets cut into the
// body's OpenVDB level set -> fragments with their §5.2 classes. Large fragments carry the
// level set with their incomplete cracks and those cracks' sheets (§5.3); the > 95 % fragment
// keeps the parent's whole state, BEM included.
//
// Cutting (§3): voxel-resolution markers (CrackFront.h) follow the coarse front in every crack
// step, slide along the level set's surface where the coarse front does (SurfaceSlide.h), stop
// at it otherwise and in cracks cut earlier, stop the coarse nodes whose markers all stopped
// (after that step's move), are carried on to the surface or another crack where the coarse
// front stopped, and the surface they swept is cut into the level set. With voxelFronts off the
// coarse BEM crack sheet is cut instead (extended to the surface where its front stopped).
#include <btFracture/core/FractureSettings.h>
#include <btFracture/dynamics/FractureEngine.h>
#include <btFracture/geometry/FragmentClasses.h>

#include <functional>
#include <memory>

namespace btfracture {

class LevelSetBody;
struct ResidentMatrices;

// The engine's own settings; a body's method, resolutions and noise are its
// FractureBodySettings.
struct BemFractureEngineSettings {
    CrackSettings fracture;      // crack initiation and propagation
    FragmentSettings fragments;  // volume classes (§5.2)
    // Cut the surface swept by the voxel-resolution crack fronts instead of the coarse crack
    // sheet (see the header comment; scene key effects.crack_cut).
    bool voxelFronts = true;
    // BEM matrices (K, F, the factor of K_R) and FULL crack systems that idle bodies may keep
    // [MB]. Before an engine call, and before a cracked body is cut, the bodies called least
    // recently release theirs (logged) until all fit; bodies called within the last 4 steps
    // keep theirs (lasting contacts). A body called again assembles and factors its BEM again
    // (the same values) and rebuilds its crack system from its cracks in one piece, which agrees
    // with the grown one to about 1e-5 in K/K_c, not bit for bit (the budget can change a
    // chaotic scene's course).
    // 0 keeps only the recent ones; infinity keeps all.
    double idleMatrixBudgetMB = 512.0;
};

class BemFractureEngine : public FractureEngine {
public:
    explicit BemFractureEngine(const BemFractureEngineSettings& settings = {});

    FractureOutcome fracture(btFractureRigidBody& body, const std::vector<BodyContact>& contacts,
                             FractureStatistics& stats) override;
    // Level-set curvature once the body has a level set, the mesh proxy before.
    double meanCurvature(const btFractureRigidBody& body, const Eigen::Vector3d& bodyPoint) const override;

    const BemFractureEngineSettings& settings() const { return settings_; }

    // Called after new cracks were cut into a body's level set (parent body frame = the level
    // set's frame for an original body), before it is split into fragments: lets an application
    // save the fractured level set (LevelSetBody::writeVdb). Runs on the stepping thread.
    using CutObserver = std::function<void(const btFractureRigidBody& body, const LevelSetBody& levelSet)>;
    void setCutObserver(CutObserver observer) { cutObserver_ = std::move(observer); }

private:
    BemFractureEngineSettings settings_;
    CutObserver cutObserver_;
    std::shared_ptr<ResidentMatrices> resident_;  // bodies whose BEM is built, for the budget
};

}  // namespace btfracture
