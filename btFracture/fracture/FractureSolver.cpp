// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/FractureSolver.h>

#include <btFracture/bem/InteriorStress.h>
#include <btFracture/bem/SurfaceStress.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/Timer.h>
#include <btFracture/fracture/CrackGrowth.h>
#include <btFracture/fracture/Initiation.h>
#include <btFracture/fracture/PropagationLaw.h>
#include <btFracture/fracture/SifEstimator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

namespace btfracture {
namespace {

// Where EST reads each front node's local stress with CrackSettings::estimatorSurfaceFronts: a node
// on the surface at the middle of its front edge, towards its neighbours inside the body if it has
// any, else its neighbours on the surface (the edge across a thin wall); every other node at itself.
std::map<int, Eigen::Vector3d> surfaceFrontStressPoints(const CrackMesh& cracks) {
    std::map<int, std::vector<int>> neighbours;
    for (const auto& e : cracks.frontEdges()) {
        neighbours[e.a].push_back(e.b);
        neighbours[e.b].push_back(e.a);
    }
    std::map<int, Eigen::Vector3d> points;
    for (const auto& [node, around] : neighbours) {
        if (!cracks.onSurface(node)) continue;
        std::vector<int> chosen;
        for (const int n : around)
            if (!cracks.onSurface(n)) chosen.push_back(n);
        if (chosen.empty()) chosen = around;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (const int n : chosen) sum += 0.5 * (cracks.node(node) + cracks.node(n));
        points[node] = sum / static_cast<double>(chosen.size());
    }
    return points;
}

}  // namespace

FractureSolver::FractureSolver(const ElasticSolver& solver, MaterialField field, FractureSettings settings)
    : solver_(solver), field_(std::move(field)), settings_(settings) {
    settings_.validate();
    active_ =
        settings_.method == FractureMethod::Estimated ? FractureMethod::Estimated : FractureMethod::Full;
    const SurfaceMesh& mesh = solver_.mesh();
    elementSize_ = settings_.crackElementSize > 0.0 ? settings_.crackElementSize : mesh.meanDiameter();
    seeded_.assign(mesh.triangleCount(), 0);
    crackLoad_ = Eigen::VectorXd::Zero(3 * mesh.nodeCount());
}

FractureSolver::~FractureSolver() = default;

std::size_t FractureSolver::crackSystemBytes() const {
    return full_ ? full_->matrixBytes() : 0;
}

void FractureSolver::beginEvent(const Eigen::VectorXd& q, const ContactEnergy& energy) {
    cracks_.refreshUnknowns(
        solver_.mesh());  // cracks may have been added from outside (pre-cracks, carried cracks)
    arrested_.resize(cracks_.nodeCount(), 0);
    tractions_ = q;
    peakStress_ = -1.0;
    strainEnergy_ = -1.0;
    releasable_ = -1.0;
    contactEnergy_ = energy;
    // One crack-free solve per event: EST's stress before its §4.3 update, FULL's right-hand side.
    load_ = solver_.load(q);
    crackFree_ = solver_.displacementsFromLoad(load_);
    if (settings_.method == FractureMethod::Hybrid && active_ == FractureMethod::Full &&
        meshElements() >= settings_.hybridElementThreshold)
        switchToEstimator();
    if (active_ == FractureMethod::Full) {
        if (!full_) full_ = std::make_unique<CrackSystem>(solver_, cracks_);
        full_->update();
        const CrackSystem::Solution s = full_->solve(q, crackFree_);
        displacements_ = s.displacements;
        solvedOpenings_ = full_->nodalOpenings(s);
        leavingOpenings_ = Eigen::VectorXd::Zero(solvedOpenings_.size());  // as EST starts an event
    } else {
        // EST: existing cracks are re-estimated as fronts move.
        crackLoad_.setZero();
        estimatedOpenings_ = Eigen::VectorXd::Zero(3 * cracks_.nodeCount());
        displacements_ = crackFree_;
    }
}

int FractureSolver::seed() {
    const Material& m = field_.material();
    const auto stresses =
        surfaceStresses(solver_.mesh(), m.youngsModulus(), m.poissonRatio(), displacements_, tractions_);
    const auto candidates = findSeedCandidates(solver_.mesh(), stresses, field_, cracks_, seeded_);
    const int seeds =
        seedCracks(cracks_, solver_.mesh(), candidates, settings_.maxNewCracksPerEvent, settings_.seedRadius,
                   settings_.crackElementSize,
                   active_ == FractureMethod::Full && settings_.surfaceSeeds ? SeedShape::SurfaceBreaking
                                                                             : SeedShape::Embedded,
                   seeded_);
    arrested_.resize(cracks_.nodeCount(), 0);
    if (seeds > 0) {
        const std::vector<int> fresh = cracks_.refreshUnknowns(solver_.mesh());
        if (active_ == FractureMethod::Full) {
            full_->update();
            const CrackSystem::Solution s = full_->solve(tractions_, crackFree_);
            displacements_ = s.displacements;
            solvedOpenings_ = full_->nodalOpenings(s);
            recordLeavingOpenings(fresh, Eigen::VectorXd::Zero(3 * fresh.size()));  // no front left them
        } else {
            const Eigen::Index oldSize = estimatedOpenings_.size();
            estimatedOpenings_.conservativeResize(3 * cracks_.nodeCount());
            estimatedOpenings_.tail(estimatedOpenings_.size() - oldSize).setZero();
        }
    }
    return seeds;
}

std::vector<FrontSifs> FractureSolver::frontSifs(bool activeOnly) {
    const Material& m = field_.material();
    auto skip = [&](const FrontSifs& f) { return activeOnly && isArrested(f.node); };
    if (active_ == FractureMethod::Full) {
        std::vector<FrontSifs> all = displacementCorrelation(cracks_, solvedOpenings_, m);
        all.erase(std::remove_if(all.begin(), all.end(), skip), all.end());
        boundByEnergy(all);
        return all;
    }
    // EST: frames from the crack geometry, SIFs from the surface-only local stress (§4.2).
    std::vector<FrontSifs> frames =
        displacementCorrelation(cracks_, Eigen::VectorXd::Zero(3 * cracks_.nodeCount()), m);
    const StressEvaluator stress(solver_.mesh(), m.youngsModulus(), m.poissonRatio(), displacements_,
                                 tractions_);
    const double limit = gainLimit();
    std::optional<StressEvaluator> crackFree;  // only the gain limit reads the crack-free stress
    if (limit > 0.0)
        crackFree.emplace(solver_.mesh(), m.youngsModulus(), m.poissonRatio(), crackFree_, tractions_);
    if (peakStress_ < 0.0)
        peakStress_ = peakStress(
            surfaceStresses(solver_.mesh(), m.youngsModulus(), m.poissonRatio(), crackFree_, tractions_));
    stressBounded_ = 0;
    auto Keff = [&](const FrontSifs& s) { return effectiveK(s.KI, s.KII, s.KIII, m.poissonRatio()); };
    std::vector<FrontSifs> out;
    out.reserve(frames.size());
    gainLimited_ = 0;
    const std::vector<double> sheetAreas = sheetAreasInBody();
    const std::map<int, Eigen::Vector3d> surfacePoints = settings_.estimatorSurfaceFronts
                                                             ? surfaceFrontStressPoints(cracks_)
                                                             : std::map<int, Eigen::Vector3d>{};
    for (const FrontSifs& f : frames) {
        if (skip(f)) continue;
        double area = 0.0;
        if (!cracks_.trianglesAtNode(f.node).empty())
            area = sheetAreas[cracks_.sheetOf(cracks_.trianglesAtNode(f.node)[0])];
        const auto surfacePoint = surfacePoints.find(f.node);
        const Eigen::Vector3d at = surfacePoint == surfacePoints.end() ? f.position : surfacePoint->second;
        Eigen::Matrix3d local = stress.stressAt(at);
        if (boundStress(local, kMaxGeometryFactor / settings_.estimatorGeometryFactor * peakStress_))
            ++stressBounded_;
        FrontSifs e =
            estimateSifs(f.frame, local, area, m.compressiveFactor(), settings_.estimatorGeometryFactor);
        if (limit > 0.0) {  // the §4.3 update raises K_eff at most `limit` times (FractureSettings)
            const double K = Keff(e), bound = limit * Keff(estimateSifs(f.frame, crackFree->stressAt(at),
                                                                        area, m.compressiveFactor(),
                                                                        settings_.estimatorGeometryFactor));
            if (K > bound) {
                const double scale = bound / K;
                e.KI *= scale, e.KII *= scale, e.KIII *= scale;
                ++gainLimited_;
            }
        }
        e.node = f.node;
        e.position = f.position;
        e.spacing = f.spacing;
        out.push_back(e);
    }
    boundByEnergy(out);
    return out;
}

// With energyBound, the step's new crack releases at most what the contacts deliver
// (energyBoundScale; fixed for the event). EST: also at most the strain energy its crack-free
// tractions store (deliverableEnergy). FULL's own solution holds its release to the cracked
// body's energy, but the quasi-static load lets a part that is all but cut off (S nearly
// singular, its sign set by rounding) release far more than the impact brought.
void FractureSolver::boundByEnergy(std::vector<FrontSifs>& out) {
    const Material& m = field_.material();
    if (strainEnergy_ < 0.0) {
        const bool full = active_ == FractureMethod::Full;
        strainEnergy_ = solver_.strainEnergy(tractions_, crackFree_);
        const double cap = full ? std::numeric_limits<double>::infinity() : strainEnergy_;
        const Eigen::VectorXd& resting = contactEnergy_.restingTractions;
        const double restingEnergy = contactEnergy_.kinetic < cap && resting.size() > 0
                                         ? solver_.strainEnergy(resting, solver_.displacements(resting))
                                         : 0.0;
        releasable_ = deliverableEnergy(cap, contactEnergy_.kinetic, restingEnergy);
        if (settings_.energyBound && releasable_ < strainEnergy_) {
            logf(contactCapLogged_ ? LogLevel::Debug : LogLevel::Info, "fracture: the tractions store ",
                 strainEnergy_, " J, the contacts deliver at most ", releasable_, " J (impacts ",
                 contactEnergy_.kinetic, " J, resting load ", restingEnergy,
                 " J); the energy bound uses the latter",
                 contactCapLogged_ ? "" : " (further events of this body: debug log)");
            contactCapLogged_ = true;
        }
    }
    energyScale_ = 1.0;
    if (!settings_.energyBound) return;
    std::vector<FrontSifs> moving;
    std::vector<double> toughness;
    for (const FrontSifs& e : out)
        if (!isArrested(e.node)) {
            moving.push_back(e);
            toughness.push_back(field_.fractureToughness(e.position));
        }
    energyScale_ =
        energyBoundScale(moving, toughness, m.youngsModulus(), m.poissonRatio(), m.compressiveFactor(),
                         settings_.frontEdgeLength * elementSize_, settings_.minimumSpeed, releasable_);
    if (energyScale_ < 1.0)
        for (FrontSifs& e : out) e.KI *= energyScale_, e.KII *= energyScale_, e.KIII *= energyScale_;
}

// §4.2's crack area A per sheet, counting only the triangles inside the body: a sheet a fragment
// carries (§5.3) is its parent's whole sheet, and the part past the fragment's surface is no
// crack of this body. Each triangle is tested once (an O(surface triangles) winding number).
std::vector<double> FractureSolver::sheetAreasInBody() {
    const SurfaceMesh& body = solver_.mesh();
    testedCentroids_.resize(cracks_.triangleCount(), Eigen::Vector3d::Constant(std::nan("")));
    triangleInBody_.resize(cracks_.triangleCount(), 0);
    for (int t = 0; t < cracks_.triangleCount(); ++t) {
        const auto& tri = cracks_.triangle(t);
        const Eigen::Vector3d centroid =
            (cracks_.node(tri[0]) + cracks_.node(tri[1]) + cracks_.node(tri[2])) / 3.0;
        if (centroid == testedCentroids_[t]) continue;
        testedCentroids_[t] = centroid;
        triangleInBody_[t] = body.encloses(centroid);
    }
    std::vector<double> areas(cracks_.sheetCount(), 0.0);
    for (int t = 0; t < cracks_.triangleCount(); ++t)
        if (triangleInBody_[t]) areas[cracks_.sheetOf(t)] += cracks_.area(t);
    return areas;
}

FractureStepRecord FractureSolver::step(int index) {
    FractureStepRecord record;
    record.step = index;
    if (settings_.method == FractureMethod::Hybrid && active_ == FractureMethod::Full &&
        meshElements() >= settings_.hybridElementThreshold)
        switchToEstimator();
    record.method = active_;
    Timer timer;
    arrested_.resize(cracks_.nodeCount(), 0);
    const std::vector<FrontSifs> sifs = frontSifs(true);
    record.sifSeconds = timer.seconds();
    record.frontNodes = static_cast<int>(sifs.size());
    record.gainLimitedNodes = active_ == FractureMethod::Estimated ? gainLimited_ : 0;
    record.stressBoundedNodes = active_ == FractureMethod::Estimated ? stressBounded_ : 0;
    if (record.stressBoundedNodes > 0)
        logf(LogLevel::Info, "fracture: step ", index, ": the local stress at ", record.stressBoundedNodes,
             " of ", record.frontNodes, " fronts exceeded ",
             kMaxGeometryFactor / settings_.estimatorGeometryFactor, " times the crack-free surface peak ",
             peakStress_, " Pa (K <= ", kMaxGeometryFactor,
             " sigma_peak sqrt(pi a)); EST used that bound there");
    record.energyScale = energyScale_;
    if (record.energyScale < 1.0)
        logf(LogLevel::Debug, "fracture: step ", index, ": ",
             active_ == FractureMethod::Full ? "FULL" : "EST", "'s SIFs scaled by ", record.energyScale,
             " so that the step's new crack releases no more than the energy of the load, ", releasable_,
             " J");
    if (record.gainLimitedNodes > 0)
        logf(LogLevel::Info, "fracture: step ", index, ": estimatorUpdateGainLimit ",
             settings_.estimatorUpdateGainLimit, " scaled down the SIFs of ", record.gainLimitedNodes, " of ",
             record.frontNodes, " fronts");

    timer.restart();
    const Material& m = field_.material();
    std::map<int, FrontAdvance> advances;
    for (const FrontSifs& f : sifs) {
        const double Kc =
            field_.fractureToughness(f.position) * (f.compressive ? m.compressiveFactor() : 1.0);
        record.maxLoadRatio =
            std::max(record.maxLoadRatio, effectiveK(f.KI, f.KII, f.KIII, m.poissonRatio()) / Kc);
        advances[f.node] =
            advanceOf(f, field_.fractureToughness(f.position), m.compressiveFactor(), m.poissonRatio(),
                      settings_.frontEdgeLength * elementSize_, settings_.minimumSpeed);
    }
    // Nodes the observer stops end this step's move level with where their markers stopped
    // (never past their own step), then stop for good.
    std::vector<int> stopAfter;
    if (observer_) {
        for (const auto& [node, stop] : observer_(cracks_, advances).stopped) {
            if (node < 0 || node >= cracks_.nodeCount() || arrested_[node]) continue;
            stopAfter.push_back(node);
            const auto a = advances.find(node);
            if (a != advances.end() && stop.allFinite())
                a->second.distance =
                    std::clamp((stop - cracks_.node(node)).dot(a->second.direction), 0.0, a->second.distance);
        }
    }
    const bool full = active_ == FractureMethod::Full;
    const GrowthResult growth =
        growFronts(cracks_, advances, solver_.mesh(), 1.5 * settings_.frontEdgeLength * elementSize_,
                   arrested_, full ? FoldGuard::Hold : FoldGuard::Off,
                   full || settings_.estimatorSurfaceFronts ? SurfaceReach::OnSurface : SurfaceReach::Inside);
    int stopped = 0;
    for (const int node : stopAfter) {
        const auto moved = growth.newNode.find(node);
        const int last = moved == growth.newNode.end() ? node : moved->second;
        if (arrested_[last]) continue;  // growth stopped it already
        arrested_[last] = 1;
        ++stopped;
    }
    record.advancedNodes = growth.advancedNodes;
    record.arrestedNodes = growth.arrestedNodes + stopped;
    if (growth.advancedNodes > 0) updateFrontState(sifs, growth.advanced);
    record.growthSeconds = timer.seconds();
    record.crackTriangles = cracks_.triangleCount();
    logf(LogLevel::Debug, "fracture: step ", index, " ", toString(active_), ": ", record.frontNodes,
         " front nodes, ", record.advancedNodes, " advanced, ", record.arrestedNodes, " arrested, ",
         growth.heldNodes, " held (would fold), max K/Kc ", record.maxLoadRatio, ", ", record.crackTriangles,
         " crack triangles");
    return record;
}

void FractureSolver::updateFrontState(const std::vector<FrontSifs>& sifs,
                                      const std::map<int, double>& advanced) {
    const std::vector<int> fresh = cracks_.refreshUnknowns(solver_.mesh());
    // §4.3: the nodes the front just left get the opening that inverting the displacement
    // correlation gives (FULL keeps them for a HYBRID switch, EST corrects the load with them).
    Eigen::VectorXd cod(3 * fresh.size());
    for (std::size_t i = 0; i < fresh.size(); ++i) {
        const int node = fresh[i];
        Eigen::Vector3d opening = Eigen::Vector3d::Zero();
        const auto moved = advanced.find(node);
        const auto f =
            std::find_if(sifs.begin(), sifs.end(), [node](const FrontSifs& s) { return s.node == node; });
        if (moved != advanced.end() && f != sifs.end())
            opening = openingFromSifs(*f, moved->second, field_.material());
        cod.segment<3>(3 * i) = opening;
    }
    if (active_ == FractureMethod::Full) {
        try {
            full_->update();
        } catch (const Error& e) {
            // With open mouths, cracks that cut the body through leave its pieces free to move
            // against each other: no equilibrium, a singular system. Growth of this event ends.
            logf(LogLevel::Info, "fracture: the crack system could not take the grown cracks (", e.what(),
                 "); every front stops (cracks that cut a body through make it singular)");
            const Eigen::Index oldSize = solvedOpenings_.size();
            solvedOpenings_.conservativeResize(3 * cracks_.nodeCount());
            solvedOpenings_.tail(solvedOpenings_.size() - oldSize).setZero();
            arrested_.assign(cracks_.nodeCount(), 1);
            recordLeavingOpenings(fresh, cod);
            return;
        }
        const CrackSystem::Solution s = full_->solve(tractions_, crackFree_);
        displacements_ = s.displacements;
        solvedOpenings_ = full_->nodalOpenings(s);
        recordLeavingOpenings(fresh, cod);
        return;
    }
    // EST: their crack-surface coupling C (never stored) corrects the load.
    const Eigen::Index oldSize = estimatedOpenings_.size();
    estimatedOpenings_.conservativeResize(3 * cracks_.nodeCount());
    estimatedOpenings_.tail(estimatedOpenings_.size() - oldSize).setZero();
    std::vector<int> unknowns;
    for (std::size_t i = 0; i < fresh.size(); ++i) {
        estimatedOpenings_.segment<3>(3 * fresh[i]) = cod.segment<3>(3 * i);
        unknowns.push_back(cracks_.unknownOf(fresh[i]));
    }
    if (!settings_.estimatorUpdate || unknowns.empty()) return;
    const CrackSurfaceCoupling coupling =
        assembleCrackSurfaceCoupling(solver_, cracks_, unknowns, CouplingBlocks::SurfaceOnly);
    crackLoad_ += coupling.C * cod;
    displacements_ = solver_.displacementsFromLoad(load_ - crackLoad_);
}

void FractureSolver::recordLeavingOpenings(const std::vector<int>& fresh, const Eigen::VectorXd& cod) {
    const Eigen::Index oldSize = leavingOpenings_.size();
    leavingOpenings_.conservativeResize(3 * cracks_.nodeCount());
    leavingOpenings_.tail(leavingOpenings_.size() - oldSize).setZero();
    for (std::size_t i = 0; i < fresh.size(); ++i)
        leavingOpenings_.segment<3>(3 * fresh[i]) = cod.segment<3>(3 * i);
}

void FractureSolver::switchToEstimator() {
    // Carry FULL's cracks over as EST would have built them (§4.3): for each node the opening
    // that inverting the correlation gave (with FULL's SIFs) when the front left it, C cod of
    // those as the crack load. The solved openings, grown since, would count the crack twice: the
    // surface-only stress of §4.2 would see its whole opening on top of the sqrt(pi a) factor
    // (measured: K_I 22-41 % above FULL's after the switch, tests/crack).
    if (full_ && cracks_.unknownCount() > 0) {
        Eigen::VectorXd cod(3 * cracks_.unknownCount());
        for (int k = 0; k < cracks_.unknownCount(); ++k)
            cod.segment<3>(3 * k) = leavingOpenings_.segment<3>(3 * cracks_.nodeOfUnknown()[k]);
        crackLoad_ = full_->surfaceLoadOf(cod);
        displacements_ = solver_.displacementsFromLoad(load_ - crackLoad_);
        estimatedOpenings_ = solvedOpenings_;
    }
    full_.reset();
    active_ = FractureMethod::Estimated;
    logf(LogLevel::Info, "fracture: HYBRID switched to the estimator at ", meshElements(), " BEM elements");
}

Eigen::VectorXd FractureSolver::nodalOpenings() const {
    Eigen::VectorXd out = active_ == FractureMethod::Full ? solvedOpenings_ : estimatedOpenings_;
    out.conservativeResize(3 * cracks_.nodeCount());
    return out;
}

FractureEventReport FractureSolver::run(const Eigen::VectorXd& q, double contactDuration,
                                        const ContactEnergy& energy) {
    FractureEventReport report;
    Timer timer;
    const bool wasFull = active_ == FractureMethod::Full;
    beginEvent(q, energy);
    report.seeds = seed();
    report.solveSeconds = timer.seconds();
    // Budget: the contact time at the Rayleigh speed, one element per step (FractureRB).
    int budget = settings_.maxStepsPerEvent;
    if (contactDuration > 0.0) {
        const double steps = contactDuration * field_.material().rayleighWaveSpeed() /
                             (settings_.frontEdgeLength * elementSize_);
        budget = std::min(budget, std::max(1, static_cast<int>(std::lround(steps))));
    }
    int scaled = 0;
    double smallestScale = 1.0;
    for (int i = 0; i < budget && !cracks_.frontEdges().empty(); ++i) {
        const FractureStepRecord r = step(i);
        report.steps.push_back(r);
        if (r.energyScale < 1.0) ++scaled, smallestScale = std::min(smallestScale, r.energyScale);
        if (r.advancedNodes == 0) break;
    }
    if (scaled > 0)
        logf(LogLevel::Info, "fracture: the energy bound scaled the SIFs of ", scaled, " of ",
             report.steps.size(), " steps (factors down to ", smallestScale,
             ") so that no step's new crack releases more than ", releasable_,
             " J, the energy of the load (each step: debug log)");
    report.switchedToEstimator = wasFull && active_ == FractureMethod::Estimated;
    return report;
}

}  // namespace btfracture
