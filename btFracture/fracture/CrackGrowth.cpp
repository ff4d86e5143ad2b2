// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/CrackGrowth.h>

#include <btFracture/core/Intersection.h>
#include <btFracture/fracture/SurfaceSlide.h>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

struct Obstacle {
    double t = 1.0;            // fraction of the segment that stays clear
    bool crack = false;        // the first obstacle is another crack (else the surface)
    int surfaceTriangle = -1;  // the body triangle hit, when the surface is the obstacle
};

// Where the segment p -> q first leaves the body or meets a crack triangle not touching `node`.
// From a point on the surface the surface is an obstacle only where the segment leaves the body
// there (SurfaceStart::Leaves), or not at all (SurfaceStart::Slides: a slide along it, which is
// put back onto the surface afterwards).
enum class SurfaceStart { Inside, Leaves, Slides };
Obstacle firstObstacle(const CrackMesh& cracks, int node, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                       const SurfaceMesh& body, SurfaceStart start = SurfaceStart::Inside) {
    Obstacle o;
    if (start == SurfaceStart::Leaves) {
        const SurfaceMesh::Nearest near = body.nearest(p);
        if (body.normal(near.triangle).dot(q - p) > 0.0) return {0.0, false, near.triangle};
    }
    for (int s = 0; s < body.triangleCount() && start != SurfaceStart::Slides; ++s) {
        const auto& tri = body.triangle(s);
        const double hit = segmentTriangleHit(p, q, body.node(tri[0]), body.node(tri[1]), body.node(tri[2]));
        if (hit >= (start == SurfaceStart::Leaves ? 1e-6 : 0.0) && hit < o.t) o = {hit, false, s};
    }
    for (int c = 0; c < cracks.triangleCount(); ++c) {
        const auto& tri = cracks.triangle(c);
        if (tri[0] == node || tri[1] == node || tri[2] == node) continue;
        const double hit =
            segmentTriangleHit(p, q, cracks.node(tri[0]), cracks.node(tri[1]), cracks.node(tri[2]));
        if (hit > 1e-9 && hit < o.t) o = {hit, true, -1};
    }
    return o;
}

// Unit tangent of the front at `node` (from its previous to its next front node).
Eigen::Vector3d frontTangent(const CrackMesh& cracks, const std::map<int, std::pair<int, int>>& neighbours,
                             int node) {
    const auto it = neighbours.find(node);
    if (it == neighbours.end()) return Eigen::Vector3d::Zero();
    const auto [previous, next] = it->second;
    const Eigen::Vector3d from = previous >= 0 ? cracks.node(previous) : cracks.node(node);
    const Eigen::Vector3d to = next >= 0 ? cracks.node(next) : cracks.node(node);
    const Eigen::Vector3d t = to - from;
    return t.norm() > 0.0 ? Eigen::Vector3d(t.normalized()) : Eigen::Vector3d::Zero();
}

// Whether triangle (a, b, c) turns less than 120 degrees from the crack normal n it grows from
// (a kink turns it by at most 70.5 degrees; a triangle laid back over the sheet by 180).
bool keepsSide(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
               const Eigen::Vector3d& n) {
    return (b - a).cross(c - a).normalized().dot(n) > -0.5;
}

// Where a moving front node goes, whether it stops there for good and whether that is on the
// surface.
struct Target {
    Eigen::Vector3d position;
    bool stops;
    bool onSurface;
};

// Drops from `targets` (old front node -> its move) the moves whose strip triangles would fold
// back over the sheet (a node stepping behind its front edge, or two neighbours crossing), one
// node at a time until none folds; such nodes stay where they are for this step. A folded sheet
// has an indefinite crack-crack block (Eq. 4), so FULL's Schur complement loses its Cholesky
// factor. Returns the number of nodes held.
int holdFoldingNodes(const CrackMesh& cracks, std::map<int, Target>& targets) {
    int held = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& e : cracks.frontEdges()) {
            const auto ia = targets.find(e.a), ib = targets.find(e.b);
            const bool movesA = ia != targets.end(), movesB = ib != targets.end();
            if (!movesA && !movesB) continue;
            const Eigen::Vector3d n = cracks.normal(e.triangle);
            const Eigen::Vector3d a = cracks.node(e.a), b = cracks.node(e.b);
            const Eigen::Vector3d a1 = movesA ? ia->second.position : a,
                                  b1 = movesB ? ib->second.position : b;
            // The strip's triangles as growFronts adds them; the node of the first that folds stays.
            auto hold = targets.end();
            if (movesA && movesB)
                hold = !keepsSide(b, a, a1, n) ? ia : !keepsSide(b, a1, b1, n) ? ib : targets.end();
            else if (movesA)
                hold = keepsSide(a, a1, b, n) ? targets.end() : ia;
            else
                hold = keepsSide(b, a, b1, n) ? targets.end() : ib;
            if (hold == targets.end()) continue;
            targets.erase(hold);
            ++held;
            changed = true;
        }
    }
    return held;
}

// Adds triangle (apex, from, to), whose edge from -> to becomes front, split at its midpoint
// when longer than maxEdge (the apex stays the same, so the orientation is kept). A midpoint
// outside the body (nodes sliding on a slightly wavy face, or an edge across a concave part)
// moves to just inside the surface, or is arrested if that fails: outside, a front would grow
// on unchecked.
int addFrontTriangle(CrackMesh& cracks, int apex, int from, int to, double maxEdge, const SurfaceMesh& body,
                     std::vector<char>& arrested, const std::vector<char>& onSurface) {
    if ((cracks.node(to) - cracks.node(from)).norm() <= maxEdge) {
        cracks.addTriangle(apex, from, to);
        return 1;
    }
    Eigen::Vector3d middle = 0.5 * (cracks.node(from) + cracks.node(to));
    if (onSurface[from] && onSurface[to]) {  // a mouth edge: its midpoint on the surface too
        const int mid = cracks.addNode(body.nearest(middle).point);
        arrested.push_back(1);
        cracks.addTriangle(apex, from, mid);
        cracks.addTriangle(apex, mid, to);
        return 2;
    }
    bool inside = body.encloses(middle);
    if (!inside) {  // to 0.05 maxEdge inside the nearest surface point, along that face's normal
        const SurfaceMesh::Nearest near = body.nearest(middle);
        middle = near.point - 0.05 * maxEdge * body.normal(near.triangle);
        inside = body.encloses(middle);
    }
    const int mid = cracks.addNode(middle);
    arrested.push_back(inside ? 0 : 1);
    cracks.addTriangle(apex, from, mid);
    cracks.addTriangle(apex, mid, to);
    return 2;
}

// FULL: the distance [max edge] from the surface within which a front step ends on it.
constexpr double kSurfaceSnap = 0.05;

}  // namespace

GrowthResult growFronts(CrackMesh& cracks, const std::map<int, FrontAdvance>& advances,
                        const SurfaceMesh& body, double maxEdge, std::vector<char>& arrested, FoldGuard guard,
                        SurfaceReach reach) {
    GrowthResult result;
    arrested.resize(cracks.nodeCount(), 0);
    // Front neighbours of every front node (previous -> node -> next along the front edges).
    std::map<int, std::pair<int, int>> neighbours;
    for (const auto& e : cracks.frontEdges()) {
        neighbours.try_emplace(e.a, -1, -1).first->second.second = e.b;
        neighbours.try_emplace(e.b, -1, -1).first->second.first = e.a;
    }
    // New node for every moving, unarrested front node (ordered by node index: deterministic).
    // A node that would cross another crack stops just before it and is arrested for good. A node
    // that would leave the body stops just inside the surface and slides on along the line where
    // its new crack plane (growth direction and front tangent) meets the surface's tangent plane,
    // by the part of the rest of its step along that line: the ends of a through crack run along
    // the faces of a thin body instead of stopping there. It is arrested only when nothing is left
    // of the slide (a front arriving square to the surface, or a corner).
    const bool toSurface = reach == SurfaceReach::OnSurface;
    const double reachFraction = toSurface ? 1.0 : 0.9;  // of the way to the surface
    // Nodes on the surface: matched ones, and (filled in below) new nodes placed on it.
    std::vector<char> onSurface(cracks.nodeCount(), 0);
    for (int i = 0; i < cracks.nodeCount(); ++i) onSurface[i] = cracks.onSurface(i);
    std::map<int, Target> targets;  // old front node -> where it moves
    for (const auto& [node, advance] : advances) {
        if (advance.distance <= 0.0 || arrested[node]) continue;
        const Eigen::Vector3d p = cracks.node(node);
        const Eigen::Vector3d step = advance.distance * advance.direction;
        const bool fromSurface = toSurface && onSurface[node];
        const Obstacle o = firstObstacle(cracks, node, p, p + step, body,
                                         fromSurface ? SurfaceStart::Leaves : SurfaceStart::Inside);
        const bool blocked = o.t < 1.0;
        Eigen::Vector3d target = p + (blocked ? (o.crack ? 0.9 : reachFraction) * o.t : 1.0) * step;
        bool stops = blocked;
        bool surfaceTarget = toSurface && blocked && !o.crack;
        if (blocked && !o.crack) {
            const SurfaceSlide slide = surfaceSlide(advance.direction, frontTangent(cracks, neighbours, node),
                                                    body.normal(o.surfaceTriangle));
            const Eigen::Vector3d move =
                (1.0 - reachFraction * o.t) * advance.distance * slide.along * slide.line;
            if (slide.slides && move.norm() >= 0.05 * maxEdge) {
                const Obstacle again = firstObstacle(cracks, node, target, target + move, body,
                                                     toSurface ? SurfaceStart::Slides : SurfaceStart::Inside);
                target += (again.t < 1.0 ? (again.crack ? 0.9 : reachFraction) * again.t : 1.0) * move;
                if (toSurface) target = body.nearest(target).point;  // a curved face
                stops = again.crack;
            }
        }
        // FULL (SurfaceReach::OnSurface): snap to the surface within kSurfaceSnap (header).
        if (toSurface && !blocked) {
            const SurfaceMesh::Nearest near = body.nearest(target);
            if (near.distance < kSurfaceSnap * maxEdge &&
                (fromSurface || near.distance < body.nearest(p).distance)) {
                target = near.point;
                surfaceTarget = true;
            }
        }
        // A node arriving at the surface goes on to it however short its step.
        const double room = surfaceTarget && !fromSurface ? 1e-6 * maxEdge : 0.05 * maxEdge;
        // No room left, or the node is (a carried crack reaching past a fragment's surface) or
        // ends outside the body: outside, a front would grow on unchecked.
        if ((target - p).norm() < room || (!surfaceTarget && !body.encloses(target))) {
            arrested[node] = 1;
            ++result.arrestedNodes;
            continue;
        }
        targets[node] = {target, stops, surfaceTarget};
    }
    if (guard == FoldGuard::Hold) result.heldNodes = holdFoldingNodes(cracks, targets);
    std::map<int, int> moved;  // old front node -> new node
    for (const auto& [node, target] : targets) {
        const int fresh = cracks.addNode(target.position);
        arrested.push_back(target.stops ? 1 : 0);
        onSurface.push_back(target.onSurface);
        if (target.stops) ++result.arrestedNodes;
        moved[node] = fresh;
        result.advanced[node] = (target.position - cracks.node(node)).norm();
    }
    result.advancedNodes = static_cast<int>(moved.size());
    result.newNode = moved;
    // A strip per front edge a -> b (interior on its left): the new triangles sit on its right,
    // and new front edges longer than maxEdge are split.
    const auto edges = cracks.frontEdges();
    for (const auto& e : edges) {
        const auto ia = moved.find(e.a), ib = moved.find(e.b);
        const bool movesA = ia != moved.end(), movesB = ib != moved.end();
        if (movesA && movesB) {
            cracks.addTriangle(e.b, e.a, ia->second);
            result.newTriangles +=
                1 + addFrontTriangle(cracks, e.b, ia->second, ib->second, maxEdge, body, arrested, onSurface);
        } else if (movesA) {  // new front a' -> b
            result.newTriangles +=
                addFrontTriangle(cracks, e.a, ia->second, e.b, maxEdge, body, arrested, onSurface);
        } else if (movesB) {  // new front a -> b'
            result.newTriangles +=
                addFrontTriangle(cracks, e.b, e.a, ib->second, maxEdge, body, arrested, onSurface);
        }
    }
    return result;
}

}  // namespace btfracture
