#include <btFracture/fracture/CrackGrowth.h>

#include <btFracture/core/Intersection.h>

#include <algorithm>

namespace btfracture {
namespace {

// Where the segment p -> q first leaves the body or meets a crack triangle not touching
// `node`; returns the fraction of the segment that stays clear (1 = all of it).
double clearFraction(const CrackMesh& cracks, int node, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                     const SurfaceMesh& body) {
    double t = 1.0;
    for (int s = 0; s < body.triangleCount(); ++s) {
        const auto& tri = body.triangle(s);
        const double hit = segmentTriangleHit(p, q, body.node(tri[0]), body.node(tri[1]), body.node(tri[2]));
        if (hit >= 0.0) t = std::min(t, hit);
    }
    for (int c = 0; c < cracks.triangleCount(); ++c) {
        const auto& tri = cracks.triangle(c);
        if (tri[0] == node || tri[1] == node || tri[2] == node) continue;
        const double hit = segmentTriangleHit(p, q, cracks.node(tri[0]), cracks.node(tri[1]), cracks.node(tri[2]));
        if (hit > 1e-9) t = std::min(t, hit);
    }
    return t;
}

}  // namespace

GrowthResult growFronts(CrackMesh& cracks, const std::map<int, FrontAdvance>& advances, const SurfaceMesh& body,
                        double maxEdge, std::vector<char>& arrested) {
    GrowthResult result;
    arrested.resize(cracks.nodeCount(), 0);
    // New node for every moving, unarrested front node (ordered by node index: deterministic).
    std::map<int, int> moved;  // old front node -> new node
    for (const auto& [node, advance] : advances) {
        if (advance.distance <= 0.0 || arrested[node]) continue;
        const Eigen::Vector3d p = cracks.node(node);
        const Eigen::Vector3d q = p + advance.distance * advance.direction;
        const double t = clearFraction(cracks, node, p, q, body);
        // Stop a little before an obstacle so the new node stays strictly inside.
        const double keep = t < 1.0 ? 0.9 * t : 1.0;
        if (keep * advance.distance < 0.05 * maxEdge) {  // blocked right away
            arrested[node] = 1;
            ++result.arrestedNodes;
            continue;
        }
        const int fresh = cracks.addNode(p + keep * advance.distance * advance.direction);
        arrested.push_back(t < 1.0 ? 1 : 0);
        if (t < 1.0) ++result.arrestedNodes;
        moved[node] = fresh;
        result.advanced[node] = keep * advance.distance;
    }
    result.advancedNodes = static_cast<int>(moved.size());
    // A strip per front edge a -> b (interior on its left): the new triangles sit on the right.
    const auto edges = cracks.frontEdges();
    for (const auto& e : edges) {
        const auto ia = moved.find(e.a), ib = moved.find(e.b);
        const bool movesA = ia != moved.end(), movesB = ib != moved.end();
        auto addSplit = [&](int apex, int from, int to) {
            // Triangle (apex, from, to) whose edge from -> to is new front: split it if too long.
            if ((cracks.node(to) - cracks.node(from)).norm() > maxEdge) {
                const int mid = cracks.addNode(0.5 * (cracks.node(from) + cracks.node(to)));
                arrested.push_back(arrested[from] && arrested[to]);
                cracks.addTriangle(apex, from, mid);
                cracks.addTriangle(apex, mid, to);
                result.newTriangles += 2;
            } else {
                cracks.addTriangle(apex, from, to);
                ++result.newTriangles;
            }
        };
        if (movesA && movesB) {
            cracks.addTriangle(e.b, e.a, ia->second);
            ++result.newTriangles;
            addSplit(e.b, ia->second, ib->second);
        } else if (movesA) {
            cracks.addTriangle(e.b, e.a, ia->second);
            ++result.newTriangles;
        } else if (movesB) {
            cracks.addTriangle(e.b, e.a, ib->second);
            ++result.newTriangles;
        }
    }
    return result;
}

}  // namespace btfracture
