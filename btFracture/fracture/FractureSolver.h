// SPDX-License-Identifier: Zlib
#pragma once
// One body's fracture simulation (paper §3-4): per event, seed cracks where the surface stress
// exceeds the strength, then step the fronts - SIFs (FULL: Eq. 4 and displacement correlation;
// EST: local stress, §4.2, with the right-hand-side update of §4.3), propagation direction and
// speed, growth of the crack sheets - until every front arrests or the step budget (the contact
// duration at crack speed, and a cap) is used. HYBRID starts FULL and switches to EST for good
// once the BEM mesh (surface + crack triangles) reaches the threshold (§4.4).
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/CrackSystem.h>
#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/FractureSettings.h>
#include <btFracture/fracture/MaterialField.h>
#include <btFracture/fracture/PropagationLaw.h>
#include <btFracture/fracture/StressIntensity.h>

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace btfracture {

struct FractureStepRecord {
    int step = 0;
    FractureMethod method = FractureMethod::Full;  // Full or Estimated
    int frontNodes = 0, advancedNodes = 0, arrestedNodes = 0;
    int crackTriangles = 0;      // after the step
    double maxLoadRatio = 0.0;   // max K_eff / K_c over the front before the step
    int gainLimitedNodes = 0;    // EST: fronts whose SIFs estimatorUpdateGainLimit scaled down
    int stressBoundedNodes = 0;  // EST: fronts whose local stress boundStress scaled down
    double energyScale = 1.0;    // factor energyBoundScale put on every SIF (1: none)
    double sifSeconds = 0.0, growthSeconds = 0.0;
};

struct FractureEventReport {
    int seeds = 0;
    bool switchedToEstimator = false;
    double solveSeconds = 0.0;  // crack-free solve and surface stress at the event start
    std::vector<FractureStepRecord> steps;
};

// What an event's contacts can deliver, for the energy bound (deliverableEnergy): the impacts'
// kinetic energy of approach, sum 1/2 m* v^2 [J] (infinite: not known; EST then keeps the
// tractions' strain energy, FULL is unbounded), and the tractions of its resting contacts (3m [Pa], balanced;
// empty: none).
struct ContactEnergy {
    double kinetic = std::numeric_limits<double>::infinity();
    Eigen::VectorXd restingTractions;
};

class FractureSolver {
public:
    // Borrows `solver` (the body's prefactored BEM), which must outlive this object.
    FractureSolver(const ElasticSolver& solver, MaterialField field, FractureSettings settings);
    ~FractureSolver();

    CrackMesh& cracks() { return cracks_; }
    const CrackMesh& cracks() const { return cracks_; }
    const ElasticSolver& solver() const { return solver_; }
    const FractureSettings& settings() const { return settings_; }
    // The method the next step uses: Full or Estimated (HYBRID resolved by the mesh size).
    FractureMethod activeMethod() const { return active_; }

    // A whole event for P0 tractions q (3m [Pa], balanced) acting for `contactDuration` [s]
    // (<= 0: only the step cap limits propagation).
    FractureEventReport run(const Eigen::VectorXd& tractions, double contactDuration,
                            const ContactEnergy& energy = {});

    // The pieces of run(), for tests and benchmarks:
    // The crack-free (EST) or current (FULL) solve and stresses; `energy` for the energy bound.
    void beginEvent(const Eigen::VectorXd& tractions, const ContactEnergy& energy = {});
    int seed();  // initiation; returns new seeds
    // SIFs of the active method now; with activeOnly, arrested front nodes are left out (EST then
    // evaluates the local stress only where the front can still move: cost ~ active front).
    std::vector<FrontSifs> frontSifs(bool activeOnly = false);
    // EST: fronts the last frontSifs() call limited (FractureSettings::estimatorUpdateGainLimit).
    int gainLimitedNodes() const { return gainLimited_; }
    // EST: fronts whose local stress the last frontSifs() call bounded (boundStress).
    int stressBoundedNodes() const { return stressBounded_; }
    // The factor the last frontSifs() call put on every SIF (energyBoundScale; 1: none), the
    // strain energy of the event's crack-free tractions [J] and what the bound lets a step
    // release (deliverableEnergy) [J].
    double energyScale() const { return energyScale_; }
    double strainEnergy() const { return strainEnergy_; }
    double releasableEnergy() const { return releasable_; }
    FractureStepRecord step(int index);  // one propagation step

    // What the high-resolution front (CrackFront.h) tells the coarse sheet after it moved: the
    // front nodes whose markers all stopped, each with where they stopped (BEM frame) [m].
    struct GrowthFeedback {
        std::map<int, Eigen::Vector3d> stopped;
    };
    // Called in every step with the front advances (BEM frame) before the sheets grow. A node it
    // stops ends this step's move level with its stop point (never past its own step; the
    // coarse sheet ends where the voxel-resolution cut did) and stops for good. Unset: none.
    using GrowthObserver =
        std::function<GrowthFeedback(const CrackMesh&, const std::map<int, FrontAdvance>&)>;
    void setGrowthObserver(GrowthObserver observer) { observer_ = std::move(observer); }

    // Front nodes that stopped for good (reached the surface head-on or met another crack).
    bool isArrested(int node) const { return node < static_cast<int>(arrested_.size()) && arrested_[node]; }

    // FULL's crack system (S, its factor, L^-1 P C): bytes held, and freeing it between events; the
    // next event builds it again from the cracks (the same equations).
    std::size_t crackSystemBytes() const;
    void releaseCrackSystem() { full_.reset(); }

    // Surface displacements of the current state (FULL: Eq. 4 solution; EST: updated, §4.3).
    const Eigen::VectorXd& displacements() const { return displacements_; }
    // COD at every crack node (FULL: solved; EST: estimated when the node left the front).
    Eigen::VectorXd nodalOpenings() const;

private:
    void boundByEnergy(std::vector<FrontSifs>& sifs);  // FractureMethodSettings::energyBound
    void updateFrontState(const std::vector<FrontSifs>& sifs, const std::map<int, double>& advanced);
    void switchToEstimator();
    void recordLeavingOpenings(const std::vector<int>& fresh, const Eigen::VectorXd& cod);
    int meshElements() const { return solver_.mesh().triangleCount() + cracks_.triangleCount(); }
    std::vector<double> sheetAreasInBody();
    // EST's §4.3 gain limit in force (0: none; FractureSettings::estimatorUpdateGainLimit).
    double gainLimit() const { return settings_.estimatorUpdate ? settings_.estimatorUpdateGainLimit : 0.0; }

    const ElasticSolver& solver_;
    MaterialField field_;
    FractureSettings settings_;
    CrackMesh cracks_;
    std::unique_ptr<CrackSystem> full_;  // FULL mode only
    FractureMethod active_;
    // Crack element size h of new front edges [m]: crackElementSize, or the mean BEM triangle
    // diameter where that is 0.
    double elementSize_ = 0.0;
    Eigen::VectorXd tractions_, load_, crackLoad_, displacements_;
    // The event's crack-free displacements (EST: before §4.3; FULL: every solve's right-hand
    // side), their peak surface stress and the tractions' strain energy (both negative until
    // computed), read by the gain limit, the stress bound and the energy bound.
    Eigen::VectorXd crackFree_;
    double peakStress_ = -1.0, strainEnergy_ = -1.0, releasable_ = -1.0;
    ContactEnergy contactEnergy_;
    bool contactCapLogged_ = false;  // the contacts' energy cap: logged as info once, then as debug
    int stressBounded_ = 0;
    double energyScale_ = 1.0;
    Eigen::VectorXd leavingOpenings_;  // FULL: per crack node, the §4.3 estimate of its opening
    int gainLimited_ = 0;
    Eigen::VectorXd estimatedOpenings_;  // EST: per crack node, 3 each
    Eigen::VectorXd solvedOpenings_;     // FULL: per crack node, 3 each
    std::vector<char> arrested_;         // per crack node
    // Per crack triangle: its centroid and whether the body's surface encloses it. Kept across
    // events (crack triangles never move); a crack mesh replaced through cracks() shows up as
    // centroids that differ, and those triangles are tested again.
    std::vector<Eigen::Vector3d> testedCentroids_;
    std::vector<char> triangleInBody_;
    std::vector<char> seeded_;  // per surface triangle
    GrowthObserver observer_;
};

}  // namespace btfracture
