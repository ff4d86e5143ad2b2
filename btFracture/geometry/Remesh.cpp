// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/Remesh.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/SelfIntersection.h>
#include <btFracture/core/Timer.h>
#include <btFracture/core/UnionFind.h>
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/EdgeLengthField.h>
#include <btFracture/geometry/HalfEdgeMesh.h>
#include <btFracture/geometry/IntersectionSmoothing.h>
#include <btFracture/geometry/MeshDebris.h>
#include <btFracture/geometry/MeshQuality.h>
#include <btFracture/geometry/QualityRepair.h>
#include <btFracture/geometry/RemeshEdits.h>
#include <btFracture/geometry/SurfaceFit.h>
#include <btFracture/geometry/ThicknessSizing.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <sstream>
#include <utility>
#include <vector>

namespace btfracture {
namespace {

constexpr int kMinTargetTriangles = 20;
constexpr double kMaxMinAngleDegrees = 35.0;
constexpr double kSplitAbove = 4.0 / 3.0;     // split edges longer than this times L
constexpr double kCollapseBelow = 4.0 / 5.0;  // collapse edges shorter than this times L
constexpr double kMinNormalCosine = 0.0;      // isotropic edits never turn a face over
// A collapse or relaxation may move the surface by at most this times L (HalfEdgeMesh::EditPreview
// deviation); without it, thin tips such as the bunny's ears erode a little every iteration.
constexpr double kMaxDeviation = 0.1;
constexpr int kMaxIntersectionRounds = 20;
// Where intersections survive smoothing, the target length is halved within this many target
// lengths of them (at most RemeshOptions::maxRefinements times) and kRefinementIterations
// iterations follow.
constexpr double kRefinementRadius = 2.0;
constexpr int kRefinementIterations = 5;
// Target lengths grow by at most this much per unit distance away from a thin part.
constexpr double kGrading = 0.5;

// Splits allowed per call, in multiples of the faces the base length needs (or of the faces
// there are, if more): sizing sites and refinement balls ask for a few times more faces at most.
constexpr long kMaxSplitsPerFace = 20;

// False, the mesh split part of the way, where the splits would exceed the limit.
bool splitLongEdges(HalfEdgeMesh& mesh, const ClosestPointTree& surface, const EdgeLengthField& field) {
    // Longest edge first: its new edges are then at most sqrt(3)/2 as long as it was (median
    // of a triangle whose longest edge is split), so this ends among degenerate triangles. Not
    // where the surface folds onto itself: a fragment's BEM source gave back an edge of the same
    // length after every split (millions, until memory ran out), hence the limit.
    double area = 0.0;
    for (int f = 0; f < mesh.faceSlots(); ++f)
        if (mesh.faceAlive(f)) area += 0.5 * mesh.faceAreaNormal(f).norm();
    const double equilateral = std::sqrt(3.0) / 4.0 * field.base() * field.base();
    const long limit = kMaxSplitsPerFace * std::max<long>(mesh.faceCount(), std::lround(area / equilateral));
    long splits = 0;
    std::priority_queue<std::pair<double, int>> queue;
    auto push = [&](int h) {
        if (mesh.twin(h) < h) h = mesh.twin(h);
        const double length = mesh.edgeLength(h);
        const Eigen::Vector3d midpoint =
            0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h)));
        if (length > kSplitAbove * field.at(midpoint)) queue.emplace(length, h);
    };
    for (int h = 0; h < mesh.halfedgeSlots(); ++h)
        if (mesh.halfedgeAlive(h) && h < mesh.twin(h)) push(h);
    while (!queue.empty()) {
        const auto [length, h] = queue.top();
        queue.pop();
        if (mesh.twin(h) < h || mesh.edgeLength(h) != length) continue;  // changed since it was queued
        if (++splits > limit) return false;
        // The midpoint goes onto the surface only when that moves it little (a tenth of the
        // edge), which keeps the new edges shorter than this one; relaxation projects the rest.
        const Eigen::Vector3d midpoint =
            0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h)));
        const Eigen::Vector3d projected = edgeMidpointOnSurface(mesh, surface, h);
        const int m = mesh.splitEdge(h, (projected - midpoint).norm() <= 0.1 * length ? projected : midpoint);
        // Every edge of the four faces at m: the split renumbered some of the outer ones.
        mesh.forEachOutgoing(m, [&](int g) {
            push(g);
            push(HalfEdgeMesh::next(g));
        });
    }
    return true;
}

void collapseShortEdges(HalfEdgeMesh& mesh, const ClosestPointTree& surface, const EdgeLengthField& field) {
    constexpr int maxSweeps = 10;
    for (int sweep = 0; sweep < maxSweeps; ++sweep) {
        int collapses = 0;
        for (int h = 0; h < mesh.halfedgeSlots(); ++h) {
            if (!mesh.halfedgeAlive(h) || mesh.twin(h) < h) continue;
            const double target =
                field.at(0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h))));
            if (mesh.edgeLength(h) >= kCollapseBelow * target) continue;
            const CollapseLimits limits{kSplitAbove * target, kMinNormalCosine, kMaxDeviation * target};
            const CollapsePlan plan = planCollapse(mesh, surface, h, limits, CollapseGoal::KeepShape);
            if (!plan.valid) continue;
            mesh.collapseEdge(h, plan.position);
            ++collapses;
        }
        if (collapses == 0) break;
    }
}

// Flips edges where that brings the four vertices closer to valence 6 (closed mesh).
void flipTowardsRegularValence(HalfEdgeMesh& mesh) {
    auto deviation = [](int a, int b, int c, int d) {
        return (a - 6) * (a - 6) + (b - 6) * (b - 6) + (c - 6) * (c - 6) + (d - 6) * (d - 6);
    };
    for (int h = 0; h < mesh.halfedgeSlots(); ++h) {
        if (!mesh.halfedgeAlive(h) || mesh.twin(h) < h) continue;
        const int a = mesh.valence(mesh.origin(h)), b = mesh.valence(mesh.target(h));
        const int c = mesh.valence(mesh.apex(h)), d = mesh.valence(mesh.apex(mesh.twin(h)));
        if (deviation(a - 1, b - 1, c + 1, d + 1) >= deviation(a, b, c, d) || !mesh.flipKeepsManifold(h))
            continue;
        if (mesh.previewFlip(h).minNormalCosine < kMinNormalCosine) continue;
        mesh.flipEdge(h);
    }
}

// Moves every vertex part of the way to the area-weighted centroid of its triangles, within its
// tangent plane, and projects it onto the surface; moves that would shift the surface by more
// than kMaxDeviation times the target length (at tips) are left out.
void relaxTangentially(HalfEdgeMesh& mesh, const ClosestPointTree& surface, double step,
                       const EdgeLengthField& field) {
    std::vector<Eigen::Vector3d> moved(mesh.vertexSlots(), Eigen::Vector3d::Zero());
    for (int v = 0; v < mesh.vertexSlots(); ++v) {
        if (!mesh.vertexAlive(v)) continue;
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        double weight = 0.0;
        mesh.forEachOutgoing(v, [&](int h) {
            const int f = HalfEdgeMesh::face(h);
            const auto tri = mesh.faceVertices(f);
            const double area = mesh.faceAreaNormal(f).norm();
            centroid += area * (mesh.position(tri[0]) + mesh.position(tri[1]) + mesh.position(tri[2])) / 3.0;
            weight += area;
        });
        const Eigen::Vector3d& p = mesh.position(v);
        const Eigen::Vector3d n = mesh.vertexNormal(v);
        Eigen::Vector3d shift =
            weight > 0.0 ? Eigen::Vector3d(centroid / weight - p) : Eigen::Vector3d::Zero();
        shift -= n * n.dot(shift);
        moved[v] = projectOntoSurface(surface, p + step * shift, n);
    }
    for (int v = 0; v < mesh.vertexSlots(); ++v)
        if (mesh.vertexAlive(v) &&
            moveDeviation(mesh, v, moved[v]) <= kMaxDeviation * field.at(mesh.position(v)))
            mesh.setPosition(v, moved[v]);
}

// One iteration of Botsch & Kobbelt's isotropic remeshing.
// False where splitting long edges did not end (splitLongEdges).
bool remeshIteration(HalfEdgeMesh& mesh, const ClosestPointTree& surface, const EdgeLengthField& field,
                     double smoothingStep) {
    if (!splitLongEdges(mesh, surface, field)) return false;
    collapseShortEdges(mesh, surface, field);
    flipTowardsRegularValence(mesh);
    relaxTangentially(mesh, surface, smoothingStep, field);
    mesh.compact();
    return true;
}

// Steers the triangle count to the target: faces scale with 1 / L^2. With `capped`, the base
// length grows to at most kMaxBaseGrowth times the one of a uniform mesh (and the sites keep
// their lengths): where thin parts ask for more triangles than the target leaves them, the
// count then stays above the target.
constexpr double kMaxBaseGrowth = 2.0;
void steerCount(const HalfEdgeMesh& mesh, EdgeLengthField& field, int targetTriangles, double uniformBase,
                bool capped) {
    const double ratio = static_cast<double>(mesh.faceCount()) / targetTriangles;
    double base = field.base() * std::clamp(std::sqrt(ratio), 0.8, 1.25);
    if (capped) base = std::min(base, kMaxBaseGrowth * uniformBase);
    field.setBase(base);
}

// Centres of the triangles that intersect others (mesh compacted: face f is triangle f).
std::vector<Eigen::Vector3d> intersectingTriangleCentres(const HalfEdgeMesh& mesh) {
    std::vector<int> faces;
    for (const auto& [a, b] : findSelfIntersections(mesh.toTriangleMesh(""))) {
        faces.push_back(a);
        faces.push_back(b);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    std::vector<Eigen::Vector3d> centres;
    for (int f : faces) {
        const auto tri = mesh.faceVertices(f);
        centres.push_back((mesh.position(tri[0]) + mesh.position(tri[1]) + mesh.position(tri[2])) / 3.0);
    }
    return centres;
}

void requireValidArguments(const std::string& source, int targetTriangles, const RemeshOptions& options) {
    if (targetTriangles < kMinTargetTriangles)
        throw Error(source + ": BEM remesh target of " + std::to_string(targetTriangles) +
                    " triangles is below the minimum of " + std::to_string(kMinTargetTriangles));
    if (options.maxRefinements < 0)
        throw Error(source + ": RemeshOptions.maxRefinements must be >= 0, got " +
                    std::to_string(options.maxRefinements));
    if (options.iterations < 1)
        throw Error(source + ": RemeshOptions.iterations must be >= 1, got " +
                    std::to_string(options.iterations));
    if (!(options.minAngleDegrees > 0.0 && options.minAngleDegrees <= kMaxMinAngleDegrees))
        throw Error(source + ": RemeshOptions.minAngleDegrees must be in (0, " +
                    std::to_string(kMaxMinAngleDegrees) + "], got " +
                    std::to_string(options.minAngleDegrees));
    if (options.repairPasses < 0)
        throw Error(source + ": RemeshOptions.repairPasses must be >= 0, got " +
                    std::to_string(options.repairPasses));
    if (!(options.smoothingStep > 0.0 && options.smoothingStep <= 1.0))
        throw Error(source + ": RemeshOptions.smoothingStep must be in (0, 1], got " +
                    std::to_string(options.smoothingStep));
    if (!(options.timeBudgetSeconds > 0.0))
        throw Error(source + ": RemeshOptions.timeBudgetSeconds must be > 0, got " +
                    std::to_string(options.timeBudgetSeconds));
}

// Throws once a remesh has used up its time budget, naming the stage it was in.
class RemeshBudget {
public:
    RemeshBudget(std::string source, int targetTriangles, double seconds)
        : source_(std::move(source)), target_(targetTriangles), seconds_(seconds) {}
    void check(const char* stage) const {
        if (timer_.seconds() <= seconds_) return;
        std::ostringstream message;
        message << source_ << ": BEM remesh at " << target_ << " triangles ran out of its time budget of "
                << seconds_ << " s during " << stage << " (" << timer_.seconds() << " s)";
        throw Error(message.str());
    }
    double seconds() const { return timer_.seconds(); }

private:
    std::string source_;
    int target_;
    double seconds_;
    Timer timer_;
};

// Drops the edge-connected components of fewer than 4 triangles (no closed surface has fewer: a
// speck of the input that the collapses shrank to two coincident zero-area triangles) and the
// vertices only they used; returns how many triangles went.
int dropSpecks(TriangleMesh& mesh) {
    const int n = static_cast<int>(mesh.triangles.size());
    UnionFind components(n);
    std::map<std::pair<int, int>, int> firstAtEdge;
    for (int t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            const auto [it, fresh] = firstAtEdge.emplace(std::minmax(a, b), t);
            if (!fresh) components.unite(t, it->second);
        }
    std::vector<int> size(n, 0);
    for (int t = 0; t < n; ++t) ++size[components.find(t)];
    std::vector<char> keep(n, 0);
    int dropped = 0;
    for (int t = 0; t < n; ++t) {
        keep[t] = size[components.find(t)] >= 4;
        dropped += keep[t] ? 0 : 1;
    }
    if (dropped == 0) return 0;
    keepTriangles(mesh, keep);
    return dropped;
}

struct RemeshContext {
    const TriangleMesh& input;
    const ClosestPointTree& surface;
    int targetTriangles;
    const RemeshOptions& options;
    double uniformBase;
    const std::vector<SizingSite>& sites;
    const std::string& source;
    const RemeshBudget& budget;
};

struct RemeshPass {
    HalfEdgeMesh mesh;
    IntersectionSmoothingResult untangle;
    QualityRepairResult repair;
    double edgeLength;  // the base target length at the end
};

enum class Sizing {
    WithinTarget,  // the sites' lengths follow the base length the triangle count steers to
    Uniform,       // no sites: one base length
    ThinPartsOwn,  // the sites keep their lengths; the base grows at most kMaxBaseGrowth times
};

// Isotropic remeshing, the angle repair and the separation of intersecting triangles (with
// local refinement where smoothing cannot separate them).
RemeshPass remeshPass(const RemeshContext& context, Sizing sizing) {
    const auto& [input, surface, targetTriangles, options, uniformBase, sites, source, budget] = context;
    RemeshPass pass{HalfEdgeMesh(input), {}, {}, 0.0};
    HalfEdgeMesh& mesh = pass.mesh;
    EdgeLengthField field(uniformBase);
    if (sizing != Sizing::Uniform)
        field.setSites(sites, uniformBase, kGrading, sizing == Sizing::WithinTarget);
    const bool capped = sizing == Sizing::ThinPartsOwn && !sites.empty();
    for (int iteration = 0; iteration < options.iterations; ++iteration) {
        if (!remeshIteration(mesh, surface, field, options.smoothingStep))
            throw Error(source + ": BEM remesh at " + std::to_string(targetTriangles) +
                        " triangles: splitting long edges does not end (the surface folds onto itself)");
        if (iteration + 2 < options.iterations) steerCount(mesh, field, targetTriangles, uniformBase, capped);
        budget.check("isotropic remeshing");
    }
    double& edgeLength = pass.edgeLength;
    edgeLength = field.base();

    const double minAngle = options.minAngleDegrees * M_PI / 180.0;
    QualityRepairResult& repair = pass.repair;
    repair = repairSmallAngles(mesh, surface, minAngle, edgeLength, options.repairPasses);
    budget.check("the angle repair");
    // Self-intersections: smooth them apart; where that fails, the surface there is too close to
    // itself for the edge length, so halve the target length around them and remesh again.
    IntersectionSmoothingResult& untangle = pass.untangle;
    int pairsBefore = std::numeric_limits<int>::max();
    for (int refinement = 0;; ++refinement) {
        untangle = smoothSelfIntersections(mesh, surface, minAngle, edgeLength, kMaxIntersectionRounds);
        budget.check("the separation of intersecting triangles");
        if (untangle.rounds > 0)
            logf(LogLevel::Info, source, ": ", untangle.moves, " vertex moves and ", untangle.edits,
                 " flips or collapses in ", untangle.rounds,
                 " rounds to separate self-intersecting triangles, ", untangle.remainingPairs, " pairs left");
        if (untangle.remainingPairs == 0 || refinement >= options.maxRefinements) break;
        // Refining that did not reduce the pairs will not (the input itself may touch or
        // intersect there); further rounds would only multiply triangles.
        if (untangle.remainingPairs >= pairsBefore) break;
        pairsBefore = untangle.remainingPairs;
        const std::vector<Eigen::Vector3d> centres = intersectingTriangleCentres(mesh);
        std::vector<double> lengths;
        for (const auto& c : centres) lengths.push_back(field.at(c));
        for (std::size_t i = 0; i < centres.size(); ++i)
            field.refine(centres[i], kRefinementRadius * lengths[i], 0.5 * lengths[i] / field.at(centres[i]));
        logf(LogLevel::Info, source, ": target edge length halved around ", centres.size(),
             " intersecting triangles");
        const HalfEdgeMesh unrefined = mesh;
        bool refined = true;
        for (int iteration = 0; iteration < kRefinementIterations && refined; ++iteration) {
            refined = remeshIteration(mesh, surface, field, options.smoothingStep);
            if (iteration + 2 < kRefinementIterations)
                steerCount(mesh, field, targetTriangles, uniformBase, capped);
            budget.check("local refinement");
        }
        if (!refined) {  // the pairs stay (warned below)
            logf(LogLevel::Info, source,
                 ": local refinement stopped, splitting long edges did not end there ",
                 "(the surface folds onto itself)");
            mesh = unrefined;
            break;
        }
        edgeLength = field.base();
        const QualityRepairResult more =
            repairSmallAngles(mesh, surface, minAngle, edgeLength, options.repairPasses);
        repair.edits += more.edits;
        repair.passes += more.passes;
        budget.check("the angle repair");
    }
    return pass;
}

}  // namespace

TriangleMesh remeshForBem(const TriangleMesh& input, int targetTriangles, const RemeshOptions& options) {
    const std::string source = input.name.empty() ? std::string("<unnamed mesh>") : input.name;
    requireValidArguments(source, targetTriangles, options);
    const RemeshBudget budget(source, targetTriangles, options.timeBudgetSeconds);
    HalfEdgeMesh checked(input);  // throws unless closed, manifold and oriented
    const ClosestPointTree surface(input);
    const double area = surfaceArea(input);
    if (!(area > 0.0) || !std::isfinite(area))
        throw Error(source + ": cannot remesh a surface of area " + std::to_string(area));

    // Edge length of equilateral triangles that tile the area with the target count.
    const double uniformBase = std::sqrt(4.0 * area / (std::sqrt(3.0) * targetTriangles));
    using Mode = RemeshOptions::ThicknessSizing;
    std::vector<SizingSite> sites;
    const RemeshContext context{input, surface, targetTriangles, options, uniformBase, sites, source, budget};
    std::vector<Sizing> order;
    if (options.thicknessSizing == Mode::Never) order = {Sizing::Uniform};
    if (options.thicknessSizing == Mode::WhenUniformFails)
        order = {Sizing::Uniform, Sizing::WithinTarget, Sizing::ThinPartsOwn};
    if (options.thicknessSizing == Mode::Always)
        order = {Sizing::WithinTarget, Sizing::Uniform, Sizing::ThinPartsOwn};
    // The first pass without intersections is kept, else the one with fewest. A sized pass
    // within the target takes triangles from the thick parts for the thin ones; one with the
    // thin parts' own lengths lets the count grow beyond the target.
    std::optional<RemeshPass> best;
    bool sized = false;
    for (const Sizing sizing : order) {
        if (best && best->untangle.remainingPairs == 0) break;
        if (sizing != Sizing::Uniform && !sized) {
            sized = true;
            sites = thicknessSizingSites(surface, uniformBase);
            logf(LogLevel::Info, source, ": ", sites.size(),
                 " places where the surface is thin and bends ask for edges shorter than ", uniformBase, " (",
                 budget.seconds(), " s)");
            budget.check("the thickness sizing");
        }
        if (sizing != Sizing::Uniform && sites.empty()) continue;
        if (best)
            logf(LogLevel::Info, source, ": ", best->untangle.remainingPairs,
                 " pairs of intersecting triangles; ",
                 sizing == Sizing::Uniform ? "remeshing with a uniform edge length"
                 : sizing == Sizing::WithinTarget
                     ? "remeshing with shorter edges at thin parts"
                     : "remeshing with the thin parts' own edge lengths beyond the target");
        RemeshPass pass = remeshPass(context, sizing);
        if (!best || pass.untangle.remainingPairs < best->untangle.remainingPairs) best = std::move(pass);
    }
    RemeshPass& pass = *best;
    HalfEdgeMesh& mesh = pass.mesh;
    const IntersectionSmoothingResult& untangle = pass.untangle;
    const QualityRepairResult& repair = pass.repair;
    const double edgeLength = pass.edgeLength;
    const double minAngle = options.minAngleDegrees * M_PI / 180.0;
    if (untangle.remainingPairs > 0)
        logf(LogLevel::Warning, source, ": BEM remesh at ", targetTriangles, " triangles still has ",
             untangle.remainingPairs,
             " pairs of intersecting triangles (parts of the input closer together than the edge length ",
             edgeLength, " allows even after local refinement); a larger target resolves them");
    if (options.fitAcrossSurface) {
        const SurfaceFitResult fit = fitAcrossSurface(mesh, surface, minAngle, kMaxDeviation * edgeLength);
        logf(LogLevel::Info, source, ": vertices moved up to ", fit.largestOffset,
             " along their normals to straddle the input surface (", fit.limitedVertices, " limited to ",
             kMaxDeviation * edgeLength, ", ", fit.keptVertices,
             " kept in place to keep angles and avoid intersections)");
    }
    mesh.compact();
    TriangleMesh output = mesh.toTriangleMesh(source + " (BEM remesh)");
    if (const int specks = dropSpecks(output); specks > 0)
        logf(
            LogLevel::Info, source, ": ", specks,
            " triangles of components too small to enclose anything (< 4 triangles) dropped from the remesh");

    const MeshQuality quality = measureQuality(output, options.minAngleDegrees);
    logf(LogLevel::Info, source, ": remeshed ", input.triangles.size(), " -> ", output.triangles.size(),
         " triangles (target ", targetTriangles, ", edge length ", edgeLength, "), min angle ",
         quality.minAngleDegrees, " deg, mean min angle ", quality.meanMinAngleDegrees, " deg, ",
         repair.edits, " repair edits in ", repair.passes, " passes, ", budget.seconds(), " s");
    if (quality.trianglesBelowAngle > 0) {
        std::ostringstream where;
        int listed = 0;
        for (int t = 0; t < quality.triangleCount && listed < 5; ++t) {
            const auto& tri = output.triangles[t];
            const Eigen::Vector3d& a = output.vertices[tri[0]];
            const Eigen::Vector3d& b = output.vertices[tri[1]];
            const Eigen::Vector3d& c = output.vertices[tri[2]];
            const double angle = triangleMinAngle(a, b, c) * 180.0 / M_PI;
            if (angle >= options.minAngleDegrees) continue;
            const Eigen::Vector3d centre = (a + b + c) / 3.0;
            where << (listed++ ? "; " : "") << "triangle " << t << " at (" << centre.x() << ", " << centre.y()
                  << ", " << centre.z() << "): " << angle << " deg";
        }
        logf(LogLevel::Warning, source, ": BEM remesh left ", quality.trianglesBelowAngle,
             " triangles below the minimum angle of ", options.minAngleDegrees,
             " deg that no local edit could fix (", where.str(),
             quality.trianglesBelowAngle > listed ? "; ..." : "", ")");
    }
    return output;
}

}  // namespace btfracture
