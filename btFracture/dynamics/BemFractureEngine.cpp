// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/BemFractureEngine.h>

#include <btFracture/bem/ElasticSolver.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/HertzContact.h>
#include <btFracture/dynamics/TractionBalance.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/fracture/CrackFront.h>
#include <btFracture/fracture/FractureSolver.h>
#include <btFracture/fracture/LevelSetFrontQueries.h>
#include <btFracture/fracture/StressIntensity.h>
#include <btFracture/geometry/LevelSetBody.h>
#include <btFracture/geometry/Remesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace btfracture {

// The states whose BEM is built, in the order they were built, each with the engine's call
// counter and the world's step at its last call (for idleMatrixBudgetMB). Shared with the
// states, which leave it when they are destroyed, so that bodies may outlive the engine.
struct ResidentMatrices {
    std::vector<FractureState*> states;  // BemFractureState
    std::uint64_t calls = 0;
};

namespace {

// Everything one body needs to break, built lazily. Positions live in the "state frame": the
// body frame of the body the state was first built for; bodyToState maps the frame of the body
// that now owns it (a fragment that kept or carried it) into that frame.
class BemFractureState : public FractureState {
public:
    Eigen::Isometry3d bodyToState = Eigen::Isometry3d::Identity();
    std::shared_ptr<LevelSetBody> levelSet;
    // Closed surface the BEM mesh is remeshed from (state frame): the body's mesh; empty for a
    // fragment until its first BEM is built from its level set (LevelSetBody::bemSourceMesh).
    TriangleMesh bemSource;
    CrackMesh carriedCracks;                // incomplete cracks inherited from a parent (state frame, §5.3)
    std::unique_ptr<ElasticSolver> solver;  // BEM frame = state frame - solver->mesh().offset()
    std::unique_ptr<TractionBalancer> balancer;   // on the BEM mesh, BEM frame
    std::unique_ptr<FractureSolver> fracture;     // borrows *solver
    std::map<int, int> cutTriangles;              // crack sheet -> triangles already cut (no markers)
    std::unique_ptr<CrackFronts> fronts;          // voxel-resolution fronts (state frame)
    FrontAdvanceResult frontTally;                // marker arrests since the last cut (logged there)
    std::shared_ptr<ResidentMatrices> resident;   // set once the BEM is built
    std::uint64_t lastCall = 0;                   // ResidentMatrices::calls at this state's last call
    std::uint64_t lastStep = 0;                   // FractureStatistics::steps at its last call
    std::string owner;                            // name of the body at its last call (for logs)
    mutable bool curvatureFailureLogged = false;  // meanCurvature logs its fallback once per state

    ~BemFractureState() override {
        if (!resident) return;
        const auto self = std::find(resident->states.begin(), resident->states.end(), this);
        if (self != resident->states.end()) resident->states.erase(self);
    }

    std::size_t matrixBytes() const {
        return (solver ? solver->matrixBytes() : 0) + (fracture ? fracture->crackSystemBytes() : 0);
    }

    // Frees the BEM and crack matrices (assembled again at the next call); returns the bytes freed.
    std::size_t releaseMatrices() {
        const std::size_t bytes = matrixBytes();
        solver->releaseMatrices();
        fracture->releaseCrackSystem();
        return bytes;
    }
};

constexpr double kBytesPerMB = 1024.0 * 1024.0;

// Bodies the engine was called for within this many steps keep their matrices whatever the
// budget: a body in lasting contact is called every step, and releasing it between two calls
// would assemble its BEM again at every step.
constexpr std::uint64_t kRecentSteps = 4;

// The states other than `inUse` (none: every state) and other than those called within the last
// kRecentSteps steps (but `justBroken`) release their BEM and crack matrices, least recently
// called first, until the rest hold at most `budgetMB`.
void releaseIdleMatrices(ResidentMatrices& resident, const BemFractureState* inUse,
                         const BemFractureState* justBroken, std::uint64_t step, double budgetMB) {
    std::vector<BemFractureState*> others;
    double total = 0.0;
    int holding = 0;
    for (FractureState* state : resident.states) {
        auto* s = static_cast<BemFractureState*>(state);
        if (s == inUse || s->matrixBytes() == 0) continue;
        total += static_cast<double>(s->matrixBytes());
        ++holding;
        if (s == justBroken || s->lastStep + kRecentSteps <= step) others.push_back(s);
    }
    logf(LogLevel::Debug, "BEM and crack matrices held by ", holding, inUse ? " other" : "",
         " bodies: ", total / kBytesPerMB, " MB (", others.size(), " of them may be released)");
    std::sort(others.begin(), others.end(),
              [](const BemFractureState* a, const BemFractureState* b) { return a->lastCall < b->lastCall; });
    for (BemFractureState* s : others) {
        if (total <= budgetMB * kBytesPerMB) break;
        const double bytes = static_cast<double>(s->releaseMatrices());
        total -= bytes;
        logf(LogLevel::Info, s->owner, ": its BEM and crack matrices (", bytes / kBytesPerMB,
             " MB) are released to keep bodies not called in the last ", kRecentSteps, " steps within ",
             budgetMB, " MB (idleMatrixBudgetMB); built again at its next call");
    }
}

void addTally(FrontAdvanceResult& into, const FrontAdvanceResult& r) {
    into.substeps += r.substeps;
    into.arrestedMarkers += r.arrestedMarkers;
    into.leftBody += r.leftBody;
    into.slid += r.slid;
    into.metCrack += r.metCrack;
    into.metSheet += r.metSheet;
    into.largestTargetShift = std::max(into.largestTargetShift, r.largestTargetShift);
}

// The coarse front of every sheet in the state frame, with each node's advance of this step.
std::map<int, CoarseFront> coarseFronts(const CrackMesh& cracks, const std::map<int, FrontAdvance>& advances,
                                        const Eigen::Vector3d& offset) {
    std::map<int, CoarseFront> out;
    for (const auto& e : cracks.frontEdges()) {
        CoarseFront& f = out[cracks.sheetOf(e.triangle)];
        f.edges.emplace_back(e.a, e.b);
        for (const int node : {e.a, e.b}) {
            f.position[node] = cracks.node(node) + offset;
            const auto a = advances.find(node);
            if (a != advances.end() && a->second.distance > 0.0)
                f.advance[node] = a->second.distance * a->second.direction;
        }
    }
    return out;
}

// The triangles of `sheet` (state frame) past the first s.cutTriangles[sheet]: those are in the
// level set already, cut by this body or, for a carried sheet, by its parent.
TriangleMesh uncutTriangles(const BemFractureState& s, const CrackMesh& cracks, int sheet,
                            const Eigen::Vector3d& offset) {
    TriangleMesh m;
    m.name = "crack sheet " + std::to_string(sheet);
    const auto cut = s.cutTriangles.find(sheet);
    int skip = cut == s.cutTriangles.end() ? 0 : cut->second;
    for (int t = 0; t < cracks.triangleCount(); ++t) {
        if (cracks.sheetOf(t) != sheet || skip-- > 0) continue;
        const int base = static_cast<int>(m.vertices.size());
        for (const int node : cracks.triangle(t)) m.vertices.push_back(cracks.node(node) + offset);
        m.triangles.push_back({base, base + 1, base + 2});
    }
    return m;
}

// Per sheet, how many triangles it has (all of them cut once sheetsToCut has run).
std::map<int, int> sheetTriangleCounts(const CrackMesh& cracks) {
    std::map<int, int> count;
    for (int t = 0; t < cracks.triangleCount(); ++t) ++count[cracks.sheetOf(t)];
    return count;
}

// FractureSolver's growth observer: moves the markers by this step's coarse advances
// (a new sheet gets markers, and its seed triangles join the surface to cut) and returns the
// coarse nodes whose markers all stopped, with where they stopped (read off the markers).
FractureSolver::GrowthFeedback advanceMarkers(BemFractureState& s, const CrackMesh& cracks,
                                              const std::map<int, FrontAdvance>& advances) {
    if (!s.fronts) s.fronts = std::make_unique<CrackFronts>(s.levelSet->voxelSize());
    const Eigen::Vector3d offset = s.solver->mesh().offset();
    const FrontQueries queries = levelSetFrontQueries(*s.levelSet);
    const std::map<int, CoarseFront> fronts = coarseFronts(cracks, advances, offset);
    for (const auto& [sheet, front] : fronts) {
        if (s.fronts->hasSheet(sheet)) continue;
        s.fronts->addSurface(sheet, uncutTriangles(s, cracks, sheet, offset));
        s.fronts->addSheet(sheet, front, queries);
    }
    const FrontAdvanceResult r = s.fronts->advance(fronts, queries);
    addTally(s.frontTally, r);
    FractureSolver::GrowthFeedback feedback;
    for (const int node : r.arrestedCoarseNodes) {
        const auto target = r.coarseTargets.find(node);  // none: it did not aim to move
        feedback.stopped[node] =
            target != r.coarseTargets.end() ? Eigen::Vector3d(target->second - offset) : cracks.node(node);
    }
    return feedback;
}

Eigen::Vector3d toState(const BemFractureState& s, const Eigen::Vector3d& bodyPoint) {
    return s.bodyToState * bodyPoint;
}

Eigen::Isometry3d fragmentFrame(const Eigen::Vector3d& centreOfMass, const Eigen::Matrix3d& inertia) {
    // The world puts a fragment's body frame at its centre of mass along principalAxes (the same
    // function), so the fragment's body point x is the parent's R x + c.
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
    frame.linear() = principalAxes(inertia).rotation;
    frame.translation() = centreOfMass;
    return frame;
}

// Voxels of a fragment's BEM source per BEM edge: coarse enough that crack-rim wedges and
// slivers vanish, fine enough that the remesher has a surface to follow (measured in
// bench_refracture_source).
constexpr double kBemSourceVoxelsPerEdge = 3.0;

// Level-set and body volumes agree within 0.1 % at the default voxel size; a larger
// difference (coarse voxels, crack slabs no piece claimed) is logged when fragment volumes are
// scaled to the body's.
constexpr double kVolumeScaleLogged = 0.01;

void buildBem(BemFractureState& s, const btFractureRigidBody& body, const CrackSettings& crack,
              bool voxelFronts, FractureStatistics& stats) {
    const FractureBodySettings& b = body.settings();
    // Sources to remesh, best first, each made only when the ones before it failed. A fragment
    // (§5.3): its solid rebuilt from its level set; the same at half the resolution (parts that
    // nearly touch merge, slivers vanish); its collision mesh (small pieces whose BEM edge spans
    // few voxels sometimes remesh only from that one); last, its level-set surface for a BEM of a
    // quarter of the triangles (edges twice as long: a small piece whose target edge spans about
    // a voxel keeps a wedge at every resolution above). An original body: its own mesh.
    struct Source {
        const char* what;
        std::function<TriangleMesh()> make;
        int target;  // BEM triangles
    };
    std::vector<Source> sources;
    const int target = b.bemTriangleTarget, coarseTarget = std::max(4, b.bemTriangleTarget / 4);
    if (s.bemSource.triangles.empty() && s.levelSet) {
        const auto fromLevelSet = [&s, &body](int triangles, double voxelsPerEdge) {
            return [&s, &body, triangles, voxelsPerEdge] {
                const Timer timer;
                TriangleMesh m = s.levelSet->bemSourceMesh(triangles, voxelsPerEdge);
                logf(LogLevel::Info, body.name(), ": BEM source of ", m.triangles.size(),
                     " triangles from its level set (", voxelsPerEdge, " voxels per edge of a ", triangles,
                     "-triangle BEM) in ", timer.seconds(), " s");
                return m;
            };
        };
        sources.push_back({"its level-set surface", fromLevelSet(target, kBemSourceVoxelsPerEdge), target});
        sources.push_back({"its level-set surface at half resolution",
                           fromLevelSet(target, 0.5 * kBemSourceVoxelsPerEdge), target});
        sources.push_back({"its collision mesh",
                           [&s, &body] {
                               TriangleMesh collision = body.mesh();
                               for (auto& v : collision.vertices) v = s.bodyToState * v;
                               return collision;
                           },
                           target});
        sources.push_back({"its level-set surface for a quarter of the BEM triangles",
                           fromLevelSet(coarseTarget, kBemSourceVoxelsPerEdge), coarseTarget});
    } else {
        sources.push_back({"its surface mesh", [&s] { return s.bemSource; }, target});
    }
    // One refinement round at most: on fragment surfaces whose parts nearly touch, more rounds
    // cost minutes and still leave intersections. A self-intersecting source cannot give a
    // valid BEM mesh: it is skipped at once instead of letting the remesher spend seconds.
    RemeshOptions remesh;
    remesh.maxRefinements = 1;
    std::string problems;
    // Any source that fails (defects, an error while it is built or remeshed, or a BEM system
    // that cannot be factored, as a remesh in disjoint parts: each part has six rigid modes, the
    // regulariser removes six in all) is noted and the next one tried.
    for (std::size_t k = 0; k < sources.size() && !s.solver; ++k) {
        const auto note = [&](const std::string& problem) {
            problems += std::string(problems.empty() ? "" : "; ") + sources[k].what + problem;
        };
        TriangleMesh source, bem;
        int parts = 0;
        try {
            source = sources[k].make();
            const MeshDefects sourceDefects = inspectMesh(source);
            if (!sourceDefects.isClosedSolid()) {
                note(" has " + sourceDefects.describe());
                continue;
            }
            bem = remeshForBem(source, sources[k].target, remesh);
            const MeshDefects defects = inspectMesh(bem);
            parts = defects.components;
            if (!defects.isClosedSolid()) {
                note(": its BEM remesh has " + defects.describe());
                continue;
            }
            bem.name = body.name() + " (BEM)";
            s.solver = std::make_unique<ElasticSolver>(SurfaceMesh(std::move(bem)), body.material());
        } catch (const Error& e) {
            note(": " + std::string(e.what()) +
                 (parts > 1 ? " (its BEM remesh has " + std::to_string(parts) + " separate parts)" : ""));
            continue;
        }
        if (k > 0)
            logf(LogLevel::Info, body.name(), ": BEM mesh from ", sources[k].what, " (", problems, ")");
        s.bemSource = std::move(source);
    }
    if (!s.solver) throw Error(body.name() + ": no BEM mesh can be built: " + problems);
    ++stats.bemBuilds;
    const SurfaceMesh& mesh = s.solver->mesh();
    TriangleMesh centred{mesh.nodes(), mesh.triangles(), body.name() + " (BEM)"};
    s.balancer = std::make_unique<TractionBalancer>(std::move(centred));
    FractureSettings settings;
    static_cast<CrackSettings&>(settings) = crack;
    static_cast<FractureMethodSettings&>(settings) = b;
    s.fracture = std::make_unique<FractureSolver>(*s.solver, MaterialField(body.material(), b.materialNoise),
                                                  settings);
    BemFractureState* state = &s;  // owned by the body, outlives its FractureSolver
    if (voxelFronts) {
        s.fracture->setGrowthObserver(
            [state](const CrackMesh& cracks, const std::map<int, FrontAdvance>& advances) {
                return advanceMarkers(*state, cracks, advances);
            });
    }
    if (s.carriedCracks.triangleCount() > 0) {
        const Eigen::Vector3d shift = -mesh.offset();
        s.carriedCracks.refreshUnknowns();
        std::vector<int> all(s.carriedCracks.sheetCount());
        for (int i = 0; i < static_cast<int>(all.size()); ++i) all[i] = i;
        CrackMesh moved = s.carriedCracks.extractSheets(all, shift);
        // The parent's sheets reach into the other fragments too. Every node of a triangle with a
        // corner outside this one is held shut, so that each opening's hat lies inside the body (a
        // hat reaching outside made S indefinite: FORMULATION.md, "Mouth").
        std::vector<char> outside(moved.nodeCount(), 0), held(moved.nodeCount(), 0);
        for (int n = 0; n < moved.nodeCount(); ++n) outside[n] = !mesh.encloses(moved.node(n));
        for (int t = 0; t < moved.triangleCount(); ++t) {
            const auto& tri = moved.triangle(t);
            if (outside[tri[0]] || outside[tri[1]] || outside[tri[2]])
                for (int n : tri) held[n] = 1;
        }
        std::vector<int> heldNodes;
        for (int n = 0; n < moved.nodeCount(); ++n)
            if (held[n]) heldNodes.push_back(n);
        moved.holdShut(heldNodes);
        moved.refreshUnknowns();
        if (!heldNodes.empty())
            logf(LogLevel::Debug, body.name(), ": ", heldNodes.size(), " of ", moved.nodeCount(),
                 " nodes of carried crack sheets lie outside the fragment or on triangles leaving it; held "
                 "shut");
        s.cutTriangles = sheetTriangleCounts(moved);  // the parent cut them
        s.fracture->cracks() = std::move(moved);
        s.carriedCracks = CrackMesh();
    }
}

// Old -> new sheet and node ids of the cracks `carried` = cracks.extractSheets(sheets, ...) took
// over: extractSheets keeps the triangles' order and their corners', so the k-th triangle of
// the selected sheets is the carried mesh's triangle k. The fragment's level set must use the
// carried sheet ids (its later cuts, crackAt and its own fragments' incomplete cracks refer to
// the crack mesh the fragment solves with), its markers both (§5.3).
struct CarriedIds {
    std::map<int, int> sheet, node;
};

CarriedIds carriedIds(const CrackMesh& cracks, const std::vector<int>& sheets, CrackMesh& carried) {
    carried.refreshUnknowns();
    CarriedIds ids;
    int k = 0;
    for (int t = 0; t < cracks.triangleCount(); ++t) {
        if (std::find(sheets.begin(), sheets.end(), cracks.sheetOf(t)) == sheets.end()) continue;
        for (int corner = 0; corner < 3; ++corner)
            ids.node.emplace(cracks.triangle(t)[corner], carried.triangle(k)[corner]);
        ids.sheet.emplace(cracks.sheetOf(t), carried.sheetOf(k++));
    }
    return ids;
}

// What to cut into the level set (state frame). Sheets with voxel-resolution markers: the
// surface they swept (seed included), after the markers of coarse nodes that stopped were
// carried up to `extension` [m] further, to the level set's surface or a crack. Any other sheet
// (fallback): its new coarse triangles plus a strip of width `extension` beyond every front
// edge whose nodes stopped. `body` names the body in the log.
std::map<int, TriangleMesh> sheetsToCut(BemFractureState& s, double extension, const std::string& body) {
    CrackMesh& cracks = s.fracture->cracks();
    cracks.refreshUnknowns();
    const Eigen::Vector3d offset = s.solver->mesh().offset();
    std::map<int, TriangleMesh> out;
    const auto marked = [&](int sheet) { return s.fronts && s.fronts->hasSheet(sheet); };
    if (s.fronts) {
        std::map<int, std::set<int>> stopped;
        for (const auto& e : cracks.frontEdges())
            for (const int node : {e.a, e.b})
                if (s.fracture->isArrested(node)) stopped[cracks.sheetOf(e.triangle)].insert(node);
        addTally(s.frontTally, s.fronts->extend(stopped, extension, levelSetFrontQueries(*s.levelSet)));
        int markers = 0, active = 0;
        for (const int sheet : s.fronts->sheets())
            for (const MarkerChain& chain : s.fronts->chains(sheet))
                for (const FrontMarker& m : chain.markers) {
                    ++markers;
                    active += m.arrested ? 0 : 1;
                }
        const FrontAdvanceResult& t = s.frontTally;
        logf(LogLevel::Info, body, ": crack fronts of ", s.fronts->sheets().size(), " sheets, ", markers,
             " markers (", active, " active), ", t.substeps, " sub-steps; arrested ", t.arrestedMarkers, " (",
             t.leftBody, " at the surface, ", t.metCrack, " in cut cracks, ", t.metSheet,
             " at other sheets, the rest at the end of their extension), ", t.slid,
             " slides along the surface, ", s.fronts->sweptTriangles(),
             " swept triangles to cut; markers up to ", t.largestTargetShift / s.levelSet->voxelSize(),
             " voxels from where their coarse nodes aimed");
        s.frontTally = FrontAdvanceResult();
        out = s.fronts->takeSwept();
    }
    const std::map<int, int> counts = sheetTriangleCounts(cracks);
    for (const auto& [sheet, count] : counts) {
        if (marked(sheet)) continue;
        TriangleMesh uncut = uncutTriangles(s, cracks, sheet, offset);
        if (!uncut.triangles.empty()) out[sheet] = std::move(uncut);
    }
    s.cutTriangles = counts;
    auto vertex = [&](TriangleMesh& m, const Eigen::Vector3d& p) {
        m.vertices.push_back(p + offset);
        return static_cast<int>(m.vertices.size()) - 1;
    };
    const auto frames = displacementCorrelation(cracks, Eigen::VectorXd::Zero(3 * cracks.nodeCount()),
                                                s.fracture->solver().material());
    std::map<int, Eigen::Vector3d> ahead;
    for (const auto& f : frames) ahead[f.node] = f.frame.ahead;
    for (const auto& e : cracks.frontEdges()) {
        const bool stopA = s.fracture->isArrested(e.a), stopB = s.fracture->isArrested(e.b);
        if ((!stopA && !stopB) || marked(cracks.sheetOf(e.triangle))) continue;
        const Eigen::Vector3d a = cracks.node(e.a), b = cracks.node(e.b);
        const Eigen::Vector3d a2 = stopA ? Eigen::Vector3d(a + extension * ahead[e.a]) : a;
        const Eigen::Vector3d b2 = stopB ? Eigen::Vector3d(b + extension * ahead[e.b]) : b;
        TriangleMesh& m = out[cracks.sheetOf(e.triangle)];
        const int ia = vertex(m, a), ib = vertex(m, b), ia2 = vertex(m, a2), ib2 = vertex(m, b2);
        m.triangles.push_back({ia, ib, ib2});
        m.triangles.push_back({ia, ib2, ia2});
    }
    return out;
}

}  // namespace

BemFractureEngine::BemFractureEngine(const BemFractureEngineSettings& settings)
    : settings_(settings), resident_(std::make_shared<ResidentMatrices>()) {
    settings_.fracture.validate("BemFractureEngine settings");
    settings_.fragments.validate();
    if (!(settings_.idleMatrixBudgetMB >= 0.0))
        throw Error(
            "BemFractureEngine settings: idleMatrixBudgetMB must be >= 0 (infinity keeps every body's), "
            "got " +
            std::to_string(settings_.idleMatrixBudgetMB));
}

double BemFractureEngine::meanCurvature(const btFractureRigidBody& body,
                                        const Eigen::Vector3d& bodyPoint) const {
    const auto* s = dynamic_cast<const BemFractureState*>(body.fractureState());
    if (!s || !s->levelSet) return FractureEngine::meanCurvature(body, bodyPoint);
    // A contact on a convex hull or decomposition can lie farther from the true surface than
    // the level set's narrow band (a concave region under a hull face): the mesh proxy answers.
    const Eigen::Vector3d p = toState(*s, bodyPoint);
    if (std::abs(s->levelSet->signedDistance(p)) >= 2.5 * s->levelSet->voxelSize()) {
        static std::once_flag logged;
        std::call_once(logged, [&] {
            logf(LogLevel::Info, body.name(),
                 ": contact point more than 2.5 voxels from the level-set surface ",
                 "(collision shape wider than the body); curvature from the mesh there. Reported once per "
                 "process");
        });
        return FractureEngine::meanCurvature(body, bodyPoint);
    }
    try {
        return s->levelSet->meanCurvature(p);
    } catch (const Error& e) {  // the projection onto the surface failed (a thin or cracked region)
        if (!s->curvatureFailureLogged)
            logf(LogLevel::Info, body.name(), ": level-set curvature failed (", e.what(),
                 "); curvature from the mesh, here and wherever it fails again on this body (not logged)");
        s->curvatureFailureLogged = true;
        return FractureEngine::meanCurvature(body, bodyPoint);
    }
}

FractureOutcome BemFractureEngine::fracture(btFractureRigidBody& body,
                                            const std::vector<BodyContact>& contacts,
                                            FractureStatistics& stats) {
    FractureOutcome outcome;
    Timer timer;
    auto* state = dynamic_cast<BemFractureState*>(body.fractureState());
    if (!state) {
        auto fresh = std::make_unique<BemFractureState>();
        fresh->bemSource = body.mesh();
        state = fresh.get();
        body.setFractureState(std::move(fresh));
    }
    BemFractureState& s = *state;
    const FractureBodySettings& b = body.settings();
    if (!s.levelSet) {
        TriangleMesh source = s.bemSource;
        source.name = body.name();
        double voxel = b.voxelSize;
        if (!(voxel > 0.0)) {
            const LevelSetBody::DefaultVoxel d = LevelSetBody::defaultVoxel(source);
            voxel = d.size;
            if (d.size > d.byThickness && d.size < d.byLength)
                logf(LogLevel::Warning, body.name(), ": level-set voxel ", d.size, " m, ",
                     LevelSetBody::kDefaultMaxVoxelsAcross, " across its longest side, puts only ",
                     d.thickness / d.size, " through its mean thickness 2V/A = ", d.thickness,
                     " m; set resolution.voxel_size to resolve it");
            else if (d.size < d.byLength)
                logf(LogLevel::Info, body.name(), ": level-set voxel ", d.size, " m, ",
                     LevelSetBody::kDefaultVoxelsThrough, " through its mean thickness 2V/A = ", d.thickness,
                     " m (the longest side / ", LevelSetBody::kDefaultVoxelsAcross, " would give ",
                     d.byLength, " m)");
        }
        s.levelSet = std::make_shared<LevelSetBody>(source, voxel);
    }
    outcome.timings.geometry += timer.seconds();

    timer.restart();
    s.owner = body.name();
    s.lastCall = ++resident_->calls;
    s.lastStep = stats.steps;
    releaseIdleMatrices(*resident_, &s, nullptr, stats.steps, settings_.idleMatrixBudgetMB);
    if (!s.solver) {
        buildBem(s, body, settings_.fracture, settings_.voxelFronts, stats);
    } else if (!s.solver->resident()) {
        s.solver->restoreMatrices();
        logf(LogLevel::Info, body.name(), ": BEM matrices of ", s.solver->mesh().triangleCount(),
             " triangles assembled and factored again in ", timer.seconds(), " s");
    }
    if (!s.resident) {
        s.resident = resident_;
        resident_->states.push_back(&s);
    }
    // Contacts into the BEM frame, then J n / (t_c A_e) on the nearest triangles, balanced (Eq. 6).
    // What they can deliver (EST's energy bound, deliverableEnergy): the impacts' kinetic energy
    // of approach, and the strain energy of the resting contacts' tractions.
    std::vector<BodyContact> local = contacts, resting;
    const Eigen::Vector3d offset = s.solver->mesh().offset();
    double duration = 0.0;
    ContactEnergy energy;
    energy.kinetic = 0.0;
    for (BodyContact& c : local) {
        c.point = toState(s, c.point) - offset;
        c.direction = s.bodyToState.linear() * c.direction;
        duration = std::max(duration, c.duration);
        if (c.approachSpeed >= kMinApproachSpeed)
            energy.kinetic += 0.5 * c.effectiveMass * c.approachSpeed * c.approachSpeed;
        else
            resting.push_back(c);
    }
    auto balancedTractions = [&](const std::vector<BodyContact>& cs) {
        const TractionField balanced = s.balancer->balance(s.balancer->contactTractions(cs));
        Eigen::VectorXd q(3 * balanced.size());
        for (std::size_t t = 0; t < balanced.size(); ++t) q.segment<3>(3 * t) = balanced[t];
        return q;
    };
    const Eigen::VectorXd q = balancedTractions(local);
    if (resting.size() == local.size())
        energy = ContactEnergy{};  // a resting load: its strain energy stands
    else if (!resting.empty())
        energy.restingTractions = balancedTractions(resting);
    outcome.timings.bem += timer.seconds();

    timer.restart();
    const int trianglesBefore = s.fracture->cracks().triangleCount();
    const FractureEventReport report = s.fracture->run(q, duration, energy);
    outcome.timings.fracture += timer.seconds() - report.solveSeconds;
    outcome.timings.bem += report.solveSeconds;
    for (const FractureStepRecord& r : report.steps)
        outcome.maxLoadRatio = std::max(outcome.maxLoadRatio, r.maxLoadRatio);
    const bool swept = s.fronts && s.fronts->sweptTriangles() > 0;
    if (s.fracture->cracks().triangleCount() == trianglesBefore && !swept) return outcome;  // nothing cracked

    timer.restart();
    // The cut and the fragments need no matrices: this body's may go too (it breaks apart, or
    // assembles them again at its next call).
    releaseIdleMatrices(*resident_, nullptr, &s, stats.steps, settings_.idleMatrixBudgetMB);
    const double meanSize = s.solver->mesh().meanDiameter();
    for (const auto& [sheet, cut] :
         sheetsToCut(s, 0.5 * meanSize + 3.0 * s.levelSet->voxelSize(), body.name())) {
        TriangleMesh named = cut;
        named.name = body.name() + " crack " + std::to_string(sheet);
        s.levelSet->cutAlongSurface(named, sheet);
    }
    outcome.crackTriangles = s.fracture->cracks().triangleCount();
    if (cutObserver_) cutObserver_(body, *s.levelSet);
    // Two pieces at least, else none is built: a body pressed again and again would mesh its one
    // piece at every call only to drop it.
    std::vector<Fragment> fragments =
        s.levelSet->fragments(settings_.fragments, b.collisionTriangleTarget, 2);
    outcome.timings.geometry += timer.seconds();
    if (fragments.size() < 2) return outcome;  // cracked, not yet apart: the cracks stay for later events

    // Mass conservation: the level set measures the body's volume only to the voxel tolerance
    // (2 % over on a slab 2 voxels thick), and the crack slabs (numerical gaps 1.7 voxels wide)
    // are shared out between the pieces only where a piece lies within a few voxels of either
    // side (pieces a few voxels across leave slab voxels unclaimed: up to 16 % of a small,
    // heavily cracked fragment's volume in the refracture chain). The body's mass is its own
    // volume (the root's is exact on its mesh), so fragment volumes and inertias scale by body
    // volume / the sum of the pieces' level-set volumes: the pieces of an event add up to the
    // parent, minus what is dropped below as unmeshable (dust of <= 1e-6 of the original volume
    // each is not in the sum and shares out too). Logged when the two differ by more than 1 %.
    double piecesVolume = 0.0;
    for (const Fragment& f : fragments) piecesVolume += f.mass.volume;
    const double volumeScale = body.volume() / piecesVolume;
    if (std::abs(volumeScale - 1.0) > kVolumeScaleLogged)
        logf(LogLevel::Info, body.name(), ": the fragments' level-set volumes sum to ", piecesVolume,
             " m^3, the body's volume is ", body.volume(), " m^3 (", 100.0 * (1.0 / volumeScale - 1.0),
             " %); fragment volumes and inertias scaled by ", volumeScale, " to conserve mass");
    const double density = body.material().density();
    const Eigen::Isometry3d parentToState = s.bodyToState;
    const Eigen::Isometry3d stateToBody = parentToState.inverse();
    // The > 95 % piece takes the state over (below), but only once the event stands: if the
    // other pieces are all dropped, the body stays as it is and so must its state's frame.
    std::shared_ptr<LevelSetBody> keptLevelSet;
    Eigen::Isometry3d keptBodyToState = parentToState;
    for (Fragment& f : fragments) {
        FragmentSpec spec;
        spec.cls = fragmentSpecClass(f.volumeClass);
        // Geometry is in the state frame; the spec is in the parent's body frame.
        spec.collisionMesh = spec.cls == FragmentSpec::Class::ConvexHull ? f.convexHull : f.collisionMesh;
        if (!holdsVolume(spec.collisionMesh, f.mass.volume, f.mass.centreOfMass)) {
            // A sliver whose mesh lost its volume in decimation: its hull, or nothing (logged).
            if (!holdsVolume(f.convexHull, f.mass.volume, f.mass.centreOfMass)) {
                logf(LogLevel::Warning, body.name(), ": fragment ", f.name, " of ", f.mass.volume,
                     " m^3 has no mesh that holds its volume and is dropped");
                continue;
            }
            spec.collisionMesh = f.convexHull;
            spec.cls = FragmentSpec::Class::ConvexHull;
        }
        for (auto& v : spec.collisionMesh.vertices) v = stateToBody * v;
        spec.volume = volumeScale * f.mass.volume;
        spec.centreOfMass = stateToBody * f.mass.centreOfMass;
        const Eigen::Matrix3d R = stateToBody.linear();
        spec.inertiaAboutCom = volumeScale * density * R * f.mass.inertiaPerDensity * R.transpose();
        const Eigen::Isometry3d childToParentBody = fragmentFrame(spec.centreOfMass, spec.inertiaAboutCom);
        if (spec.cls == FragmentSpec::Class::KeepsParentSolver) {
            keptBodyToState = parentToState * childToParentBody;
            keptLevelSet = f.levelSet;
        } else if (spec.cls == FragmentSpec::Class::Breakable) {
            auto carried = std::make_unique<BemFractureState>();
            carried->bodyToState = parentToState * childToParentBody;
            carried->levelSet = f.levelSet;  // its BEM source is made from it when first needed
            if (!f.incompleteCracks.empty()) {
                carried->carriedCracks = s.fracture->cracks().extractSheets(f.incompleteCracks, offset);
                const CarriedIds ids =
                    carriedIds(s.fracture->cracks(), f.incompleteCracks, carried->carriedCracks);
                carried->levelSet->renameCracks(ids.sheet);
                if (s.fronts) {
                    // The fragment's state frame is the parent's: the markers go on from where they are.
                    carried->fronts =
                        std::make_unique<CrackFronts>(s.fronts->extractSheets(ids.sheet, ids.node));
                    const int freed = carried->fronts->freeOutside(levelSetFrontQueries(*carried->levelSet));
                    logf(LogLevel::Info, body.name(), ": fragment ", f.name, " carries ", ids.sheet.size(),
                         " incomplete cracks and their markers (", freed,
                         " outside it follow their coarse front)");
                }
            }
            spec.carriedState = std::move(carried);
        }
        outcome.fragments.push_back(std::move(spec));
    }
    if (outcome.fragments.size() < 2) {
        outcome.fragments.clear();
        return outcome;
    }
    if (keptLevelSet) {
        // The state moves on with the kept fragment: its BEM, cracks and its own level set.
        s.bodyToState = keptBodyToState;
        s.levelSet = keptLevelSet;
        if (s.fronts) {
            const int freed = s.fronts->freeOutside(levelSetFrontQueries(*s.levelSet));
            if (freed > 0)
                logf(LogLevel::Info, body.name(), ": ", freed,
                     " crack front markers outside the kept fragment follow their coarse front freely");
        }
        s.bemSource = TriangleMesh();  // the solver is kept; a rebuild would start from the level set
    } else if (s.solver->resident()) {
        // The body is gone, replaced by its fragments: its matrices go now, not when the idle
        // budget runs out (built again should it ever be called again).
        const double bytes = static_cast<double>(s.releaseMatrices());
        logf(LogLevel::Debug, body.name(), ": its BEM and crack matrices (", bytes / kBytesPerMB,
             " MB) are released: it broke into fragments");
    }
    logf(LogLevel::Info, body.name(), ": ", report.seeds, " new cracks, ", report.steps.size(), " steps, ",
         outcome.fragments.size(), " fragments");
    return outcome;
}

}  // namespace btfracture
