#include <btFracture/fracture/CrackGrowth.h>

#include <btFracture/core/Intersection.h>

#include <algorithm>

namespace btfracture {
namespace {

struct Obstacle {
    double t = 1.0;      // fraction of the segment that stays clear
    bool crack = false;  // the first obstacle is another crack (else the surface)
};

// Where the segment p -> q first leaves the body or meets a crack triangle not touching `node`.
Obstacle firstObstacle(const CrackMesh& cracks, int node, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                       const SurfaceMesh& body) {
    Obstacle o;
    for (int s = 0; s < body.triangleCount(); ++s) {
        const auto& tri = body.triangle(s);
        const double hit = segmentTriangleHit(p, q, body.node(tri[0]), body.node(tri[1]), body.node(tri[2]));
        if (hit >= 0.0 && hit < o.t) o = {hit, false};
    }
    for (int c = 0; c < cracks.triangleCount(); ++c) {
        const auto& tri = cracks.triangle(c);
        if (tri[0] == node || tri[1] == node || tri[2] == node) continue;
        const double hit =
            segmentTriangleHit(p, q, cracks.node(tri[0]), cracks.node(tri[1]), cracks.node(tri[2]));
        if (hit > 1e-9 && hit < o.t) o = {hit, true};
    }
    return o;
}

// Adds triangle (apex, from, to), whose edge from -> to becomes front, split at its midpoint
// when longer than maxEdge (the apex stays the same, so the orientation is kept).
int addFrontTriangle(CrackMesh& cracks, int apex, int from, int to, double maxEdge,
                     std::vector<char>& arrested) {
    if ((cracks.node(to) - cracks.node(from)).norm() <= maxEdge) {
        cracks.addTriangle(apex, from, to);
        return 1;
    }
    const int mid = cracks.addNode(0.5 * (cracks.node(from) + cracks.node(to)));
    arrested.push_back(0);
    cracks.addTriangle(apex, from, mid);
    cracks.addTriangle(apex, mid, to);
    return 2;
}

}  // namespace

GrowthResult growFronts(CrackMesh& cracks, const std::map<int, FrontAdvance>& advances,
                        const SurfaceMesh& body, double maxEdge, std::vector<char>& arrested) {
    GrowthResult result;
    arrested.resize(cracks.nodeCount(), 0);
    // New node for every moving, unarrested front node (ordered by node index: deterministic).
    // A node that would leave the body or cross another crack stops just before the obstacle and
    // is arrested for good.
    std::map<int, int> moved;  // old front node -> new node
    for (const auto& [node, advance] : advances) {
        if (advance.distance <= 0.0 || arrested[node]) continue;
        const Eigen::Vector3d p = cracks.node(node);
        const Eigen::Vector3d step = advance.distance * advance.direction;
        const Obstacle o = firstObstacle(cracks, node, p, p + step, body);
        const bool blocked = o.t < 1.0;
        const Eigen::Vector3d target = p + (blocked ? 0.9 * o.t : 1.0) * step;
        if ((target - p).norm() < 0.05 * maxEdge) {  // no room left
            arrested[node] = 1;
            ++result.arrestedNodes;
            continue;
        }
        const int fresh = cracks.addNode(target);
        const bool stops = blocked;
        arrested.push_back(stops ? 1 : 0);
        if (stops) ++result.arrestedNodes;
        moved[node] = fresh;
        result.advanced[node] = (target - p).norm();
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
                1 + addFrontTriangle(cracks, e.b, ia->second, ib->second, maxEdge, arrested);
        } else if (movesA) {  // new front a' -> b
            result.newTriangles += addFrontTriangle(cracks, e.a, ia->second, e.b, maxEdge, arrested);
        } else if (movesB) {  // new front a -> b'
            result.newTriangles += addFrontTriangle(cracks, e.b, e.a, ib->second, maxEdge, arrested);
        }
    }
    return result;
}

}  // namespace btfracture
