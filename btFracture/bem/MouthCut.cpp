// SPDX-License-Identifier: Zlib
#include <btFracture/bem/MouthCut.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>

namespace btfracture {
namespace {

struct Vertex {
    Eigen::Vector3d x;
    int id;
    MouthWeights weights;
};

// A small triangulation refined by point insertion and edge splits; every triangle keeps the
// orientation and the owner (surface or crack triangle) of the one it was split from.
class LocalMesh {
public:
    struct Triangle {
        std::array<int, 3> corners;
        int owner;
    };
    std::vector<Vertex> vertices;
    std::vector<Triangle> triangles;
    std::map<std::pair<int, int>, int> splits;  // edge (lower, higher vertex) -> vertex it was split at

    int addVertex(Vertex v) {
        vertices.push_back(std::move(v));
        return static_cast<int>(vertices.size()) - 1;
    }
    // Splits every triangle with edge a-b at the new vertex.
    int splitEdge(int a, int b, Vertex v) {
        const int k = addVertex(std::move(v));
        splits[{std::min(a, b), std::max(a, b)}] = k;
        const std::size_t count = triangles.size();
        for (std::size_t i = 0; i < count; ++i) {
            const auto c = triangles[i].corners;
            for (int j = 0; j < 3; ++j) {
                const int p = c[j], q = c[(j + 1) % 3], r = c[(j + 2) % 3];
                if (!((p == a && q == b) || (p == b && q == a))) continue;
                triangles[i].corners = {p, k, r};
                triangles.push_back({{k, q, r}, triangles[i].owner});
                break;
            }
        }
        return k;
    }
    int splitTriangle(int i, Vertex v) {
        const int k = addVertex(std::move(v));
        const auto [a, b, c] = triangles[i].corners;
        triangles[i].corners = {a, b, k};
        triangles.push_back({{b, c, k}, triangles[i].owner});
        triangles.push_back({{c, a, k}, triangles[i].owner});
        return k;
    }
    int edgeUses(int a, int b) const {
        int uses = 0;
        for (const Triangle& t : triangles)
            for (int j = 0; j < 3; ++j)
                uses += (t.corners[j] == a && t.corners[(j + 1) % 3] == b) ||
                        (t.corners[j] == b && t.corners[(j + 1) % 3] == a);
        return uses;
    }
    bool hasEdge(int a, int b) const { return edgeUses(a, b) > 0; }
    // Inserts a point lying on the mesh within `tolerance` (merging with a vertex that close, else
    // splitting the edge or triangle it lies on); -1 if it lies on no triangle.
    int insert(Vertex v, double tolerance) {
        for (int i = 0; i < static_cast<int>(vertices.size()); ++i)
            if ((vertices[i].x - v.x).norm() <= tolerance) return i;
        int best = -1;
        double bestDistance = tolerance;
        for (int i = 0; i < static_cast<int>(triangles.size()); ++i) {
            const double d = distanceTo(i, v.x);
            if (d <= bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        if (best < 0) return -1;
        const auto& c = triangles[best].corners;
        for (int j = 0; j < 3; ++j) {
            const Eigen::Vector3d on =
                closestPointOnSegment(v.x, vertices[c[j]].x, vertices[c[(j + 1) % 3]].x);
            if ((on - v.x).norm() <= tolerance) return splitEdge(c[j], c[(j + 1) % 3], std::move(v));
        }
        return splitTriangle(best, std::move(v));
    }
    // Appends the vertices from a (excluded) to b (included) along the edge a-b as it was before
    // later splits.
    void appendEdge(int a, int b, std::vector<int>& out) const {
        const auto it = splits.find({std::min(a, b), std::max(a, b)});
        if (it == splits.end()) {
            out.push_back(b);
            return;
        }
        appendEdge(a, it->second, out);
        appendEdge(it->second, b, out);
    }
    double distanceTo(int i, const Eigen::Vector3d& p) const {
        const auto& c = triangles[i].corners;
        return (p - closestPointOnTriangle(p, vertices[c[0]].x, vertices[c[1]].x, vertices[c[2]].x)).norm();
    }
};

MouthWeights weightsAlong(const CrackMesh& cracks, int a, int b, const Eigen::Vector3d& x) {
    const Eigen::Vector3d ab = cracks.node(b) - cracks.node(a);
    const double s = std::clamp((x - cracks.node(a)).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return {{a, 1.0 - s}, {b, s}};
}

Panel panelOfCorners(const LocalMesh& local, const std::array<int, 3>& c, const Eigen::Vector3d& side) {
    Panel p{{local.vertices[c[0]].id, local.vertices[c[1]].id, local.vertices[c[2]].id},
            {local.vertices[c[0]].x, local.vertices[c[1]].x, local.vertices[c[2]].x},
            Eigen::Vector3d::Zero(),
            0.0};
    const Eigen::Vector3d n = (p.corners[1] - p.corners[0]).cross(p.corners[2] - p.corners[0]);
    p.area = 0.5 * n.norm();
    p.normal = n.dot(side) >= 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d(-n.normalized());
    return p;
}

// A piece with (numerically) no area: a cut point that fell on a corner. It adds nothing to any
// integral, and its hats' gradients would divide by zero.
bool hasNoArea(const Panel& p) {
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
        longest = std::max(longest, (p.corners[(k + 1) % 3] - p.corners[k]).squaredNorm());
    return !(p.area > 1e-12 * longest);
}

}  // namespace

int mouthIdOf(const SurfaceMesh& mesh, const CrackMesh& cracks, int crackNode) {
    const int s = cracks.surfaceNodeOf(crackNode);
    return s >= 0 ? s : mesh.nodeCount() + crackNode;
}

MouthCut cutAlongMouths(const SurfaceMesh& mesh, const CrackMesh& cracks) {
    MouthCut out;
    struct Segment {
        int a, b, triangle;
    };
    std::vector<Segment> segments;
    for (const auto& e : cracks.boundaryEdges())
        if (cracks.isMouthEdge(e.a, e.b)) segments.push_back({e.a, e.b, e.triangle});
    std::set<int> boundaryOnSurface;  // crack nodes on the sheets' boundary and on the surface
    for (const auto& e : cracks.boundaryEdges())
        for (int i : {e.a, e.b})
            if (cracks.onSurface(i)) boundaryOnSurface.insert(i);
    const std::vector<int> surfaceNodes(boundaryOnSurface.begin(), boundaryOnSurface.end());
    if (surfaceNodes.empty()) return out;

    const int n = mesh.nodeCount();
    const double tolerance = 1e-9 * mesh.radius();
    // The nearest point of the mouth line (or of a crack node on the surface) to x, of one mouth
    // chain or (-1) of any: its distance, the side of x (along the crack normal there) and the crack
    // hats' trace there.
    struct NearestMouth {
        double distance = std::numeric_limits<double>::infinity();
        double side = 0.0;
        MouthWeights weights;
    };
    // Mouth chains: the connected runs of mouth edges (filled once the edges are followed). Each
    // chain has its own sides: a sheet whose mouth crosses another's, or that leaves the surface
    // and comes back to it, has its cut hats jump only across the chain of their own nodes.
    std::map<int, int> chainOfNode;  // crack node on the surface -> its chain
    auto nearestMouth = [&](const Eigen::Vector3d& x, int chain = -1) {
        NearestMouth best;
        for (const Segment& s : segments) {
            if (chain >= 0 && chainOfNode.at(s.a) != chain) continue;
            const Eigen::Vector3d c = closestPointOnSegment(x, cracks.node(s.a), cracks.node(s.b));
            const double d = (x - c).norm();
            if (d < best.distance)
                best = {d, (x - c).dot(cracks.normal(s.triangle)), weightsAlong(cracks, s.a, s.b, c)};
        }
        for (int i : surfaceNodes) {
            if (chain >= 0 && chainOfNode.at(i) != chain) continue;
            const double d = (x - cracks.node(i)).norm();
            if (d < best.distance) {
                Eigen::Vector3d normal = Eigen::Vector3d::Zero();
                for (int t : cracks.trianglesAtNode(i)) normal += cracks.normal(t);
                best = {d, (x - cracks.node(i)).dot(normal), {{i, 1.0}}};
            }
        }
        return best;
    };
    // The surface triangles near the mouth: within a quarter of a segment's length of it (boxes), or
    // holding a crack node, and every triangle sharing a node with those (so that splitting an edge
    // of the first splits both its triangles).
    std::set<int> near;
    auto boxTouches = [&](int t, Eigen::Vector3d lo, Eigen::Vector3d hi) {
        Eigen::Vector3d tlo = mesh.node(mesh.triangle(t)[0]), thi = tlo;
        for (int s : mesh.triangle(t)) {
            tlo = tlo.cwiseMin(mesh.node(s));
            thi = thi.cwiseMax(mesh.node(s));
        }
        return (tlo.array() <= hi.array()).all() && (thi.array() >= lo.array()).all();
    };
    for (int i : surfaceNodes) {
        const SurfaceMesh::Nearest nearest = mesh.nearest(cracks.node(i));
        near.insert(nearest.triangle);
        if (cracks.surfaceNodeOf(i) >= 0)
            for (int t : mesh.trianglesAtNode(cracks.surfaceNodeOf(i))) near.insert(t);
    }
    for (const Segment& s : segments) {
        const Eigen::Vector3d a = cracks.node(s.a), b = cracks.node(s.b);
        const double pad = 0.25 * (b - a).norm() + tolerance;
        const Eigen::Vector3d lo = a.cwiseMin(b).array() - pad, hi = a.cwiseMax(b).array() + pad;
        for (int t = 0; t < mesh.triangleCount(); ++t)
            if (boxTouches(t, lo, hi)) near.insert(t);
    }
    // The cut hats reach past the mouth line into the + side: a surface node there closer to the
    // mouth than its shortest surface edge takes the trace at the nearest mouth point (a plateau),
    // so the hats fall to zero only over whole surface triangles, where the continuous u can
    // follow them (the Heaviside enrichment of XFEM). Without this, a mouth passing close to
    // surface nodes on its + side gives its hats the slope of that small gap (K_I of a shifted
    // edge crack 24 % low).
    std::map<int, MouthWeights> extension;  // surface node -> its cut hat values
    std::map<int, double> reach;            // surface node -> its shortest edge [m]
    {
        std::set<int> candidates;
        for (int t : near)
            for (int v : mesh.triangle(t)) candidates.insert(v);
        for (int v : candidates) {
            double shortest = std::numeric_limits<double>::infinity();
            for (int t : mesh.trianglesAtNode(v))
                for (int k = 0; k < 3; ++k)
                    if (mesh.triangle(t)[k] == v)
                        for (int other : {mesh.triangle(t)[(k + 1) % 3], mesh.triangle(t)[(k + 2) % 3]})
                            shortest = std::min(shortest, (mesh.node(other) - mesh.node(v)).norm());
            reach[v] = shortest;
            const NearestMouth m = nearestMouth(mesh.node(v));
            if (!(m.side > 0.0) || m.distance >= shortest) continue;
            extension[v] = m.weights;
        }
        for (const auto& [v, w] : extension)
            for (int t : mesh.trianglesAtNode(v)) near.insert(t);
    }
    std::set<int> ring;
    for (int t : near)
        for (int s : mesh.triangle(t))
            for (int u : mesh.trianglesAtNode(s)) ring.insert(u);

    LocalMesh local;
    std::map<int, int> localOfSurfaceNode;
    for (int t : ring) {
        std::array<int, 3> c;
        for (int k = 0; k < 3; ++k) {
            const int s = mesh.triangle(t)[k];
            auto it = localOfSurfaceNode.find(s);
            if (it == localOfSurfaceNode.end())
                it = localOfSurfaceNode.emplace(s, local.addVertex({mesh.node(s), s, {}})).first;
            c[k] = it->second;
        }
        local.triangles.push_back({c, t});
    }
    std::map<int, int> localOfCrackNode;
    for (int i : surfaceNodes) {
        const int v = local.insert({cracks.node(i), mouthIdOf(mesh, cracks, i), {{i, 1.0}}}, tolerance);
        if (v < 0)
            throw Error("crack mouth: crack node " + std::to_string(i) +
                        " lies on the surface but not near it");
        local.vertices[v].weights = {{i, 1.0}};
        localOfCrackNode[i] = v;
    }
    // Follow every mouth edge over the surface where its crack plane cuts it.
    int nextId = n + cracks.nodeCount();
    std::map<std::pair<int, int>, std::vector<int>> pathOf;  // (a, b) -> local vertices strictly between
    // `longest`: a path longer than that has strayed.
    auto follow = [&](const Segment& s, const Eigen::Vector3d& m, double longest, std::vector<int>& path) {
        const int target = localOfCrackNode.at(s.b);
        const Eigen::Vector3d origin = cracks.node(s.a);
        const double length = (cracks.node(s.b) - origin).norm();
        const double snap = 1e-6 * length + tolerance;
        int current = localOfCrackNode.at(s.a);
        // The plane meets the surface in a curve: leave the start toward the other node, then go
        // on the way the curve goes (it may turn round a corner of the body), never back.
        Eigen::Vector3d heading = (local.vertices[target].x - local.vertices[current].x).normalized();
        std::set<int> visited{current};
        double walked = 0.0;
        for (int guard = 0; !local.hasEdge(current, target); ++guard) {
            if (guard > 1000 || current == target || walked > longest) return false;
            const Eigen::Vector3d from = local.vertices[current].x;
            double bestScore = -0.5;
            int bestVertex = -1;
            std::array<int, 2> bestEdge{-1, -1};
            Eigen::Vector3d bestPoint;
            for (const auto& t : local.triangles) {
                const auto& c = t.corners;
                const int j = static_cast<int>(std::find(c.begin(), c.end(), current) - c.begin());
                if (j == 3) continue;
                const int u = c[(j + 1) % 3], w = c[(j + 2) % 3];
                const double du = m.dot(local.vertices[u].x - origin),
                             dw = m.dot(local.vertices[w].x - origin);
                auto consider = [&](const Eigen::Vector3d& x, int vertex, std::array<int, 2> edge) {
                    const Eigen::Vector3d d = x - from;
                    if (d.norm() <= tolerance || (vertex >= 0 && visited.count(vertex))) return;
                    const double score = d.normalized().dot(heading);
                    if (score > bestScore) {
                        bestScore = score;
                        bestVertex = vertex;
                        bestEdge = edge;
                        bestPoint = x;
                    }
                };
                if (std::abs(du) <= snap) consider(local.vertices[u].x, u, {-1, -1});
                if (std::abs(dw) <= snap) consider(local.vertices[w].x, w, {-1, -1});
                if ((du > snap && dw < -snap) || (du < -snap && dw > snap))
                    consider(
                        local.vertices[u].x + du / (du - dw) * (local.vertices[w].x - local.vertices[u].x),
                        -1, {u, w});
            }
            // The region cut must stay closed around the path (both triangles of every edge split).
            if (bestScore <= -0.5 || (bestVertex < 0 && local.edgeUses(bestEdge[0], bestEdge[1]) != 2))
                return false;
            if (bestVertex < 0) {
                // Other paths' traces on the split edge, interpolated (mouths crossing).
                const Vertex &u = local.vertices[bestEdge[0]], &w = local.vertices[bestEdge[1]];
                const double t = (bestPoint - u.x).norm() / (w.x - u.x).norm();
                MouthWeights weights = weightsAlong(cracks, s.a, s.b, bestPoint);
                for (const auto& [end, factor] : {std::pair<const Vertex*, double>{&u, 1.0 - t}, {&w, t}})
                    for (const auto& [node, value] : end->weights) {
                        if (node == s.a || node == s.b) continue;
                        auto it = std::find_if(weights.begin(), weights.end(),
                                               [node = node](const auto& nv) { return nv.first == node; });
                        if (it == weights.end())
                            weights.emplace_back(node, factor * value);
                        else
                            it->second += factor * value;
                    }
                bestVertex =
                    local.splitEdge(bestEdge[0], bestEdge[1], {bestPoint, nextId++, std::move(weights)});
            } else {
                MouthWeights& weights = local.vertices[bestVertex].weights;
                if (std::none_of(weights.begin(), weights.end(),
                                 [&](const auto& nv) { return nv.first == s.a || nv.first == s.b; })) {
                    const MouthWeights along = weightsAlong(cracks, s.a, s.b, local.vertices[bestVertex].x);
                    weights.insert(weights.end(), along.begin(), along.end());
                }
            }
            if (bestVertex != target) path.push_back(bestVertex);
            walked += (local.vertices[bestVertex].x - from).norm();
            heading = (local.vertices[bestVertex].x - from).normalized();
            visited.insert(bestVertex);
            current = bestVertex;
        }
        return true;
    };
    // Each mouth edge is followed in its crack plane, else (where that plane leaves the surface
    // away from the chord, on a curved surface) in the normal section through the chord: the
    // plane through both nodes that contains the mean surface normal there. An edge that neither
    // leads along is left out of the cut, counted; its nodes keep their openings, whose cut hats
    // then lack that edge's part.
    std::vector<Segment> followed;
    for (const Segment& s : segments) {
        const LocalMesh before = local;
        const int idBefore = nextId;
        const Eigen::Vector3d a = cracks.node(s.a), b = cracks.node(s.b);
        const int atA = mesh.nearest(a).triangle;
        // A path longer than twice the chord (round a corner: up to sqrt 2) and two surface
        // edges (a step may cross a whole triangle) strays.
        double edge = 0.0;
        for (int k = 0; k < 3; ++k)
            edge = std::max(
                edge, (mesh.node(mesh.triangle(atA)[k]) - mesh.node(mesh.triangle(atA)[(k + 1) % 3])).norm());
        const double longest = 2.0 * (b - a).norm() + 2.0 * edge;
        auto tryPlane = [&](const Eigen::Vector3d& plane) {
            std::vector<int> path;
            if (plane.allFinite() && follow(s, plane, longest, path)) {
                pathOf[{s.a, s.b}] = path;
                followed.push_back(s);
                return true;
            }
            local = before;
            nextId = idBefore;
            return false;
        };
        if (tryPlane(cracks.normal(s.triangle)) ||
            tryPlane((b - a).cross(mesh.normal(atA) + mesh.normal(mesh.nearest(b).triangle)).normalized()))
            continue;
        out.unfollowedEdges.emplace_back(s.a, s.b);
        logf(LogLevel::Debug, "crack mouth: the sheet edge from crack node ", s.a, " to ", s.b,
             " could not be followed over the body's surface; it is left out of the mouth's cut");
    }
    if (followed.size() < segments.size()) {
        segments = followed;  // the sides and plateau values from the followed edges only
        for (auto it = extension.begin(); it != extension.end();) {
            const NearestMouth m = nearestMouth(mesh.node(it->first));
            if (m.side > 0.0 && m.distance < reach.at(it->first)) {
                it->second = m.weights;
                ++it;
            } else {
                it = extension.erase(it);
            }
        }
    }
    {
        std::map<int, int> parent;
        std::function<int(int)> root = [&](int i) {
            const auto it = parent.find(i);
            return it == parent.end() || it->second == i ? i : (it->second = root(it->second));
        };
        for (int i : surfaceNodes) parent[i] = i;
        for (const Segment& s : segments) {
            const int a = root(s.a), b = root(s.b);
            parent[std::max(a, b)] = std::min(a, b);
        }
        for (int i : surfaceNodes) chainOfNode[i] = root(i);
    }
    // Corner values: on the mouth the traces, else the extension values.
    auto cornerWeights = [&](int v) -> const MouthWeights* {
        if (!local.vertices[v].weights.empty()) return &local.vertices[v].weights;
        const auto it = local.vertices[v].id < n ? extension.find(local.vertices[v].id) : extension.end();
        return it == extension.end() ? nullptr : &it->second;
    };
    // Mouth edges of the cut (local vertex pair -> the chains it belongs to), from each edge's path
    // with the points that later walks inserted into it.
    std::map<std::pair<int, int>, std::set<int>> mouthEdge;
    std::map<std::pair<int, int>, std::vector<int>> cutPathOf;  // (a, b) -> local vertices strictly between
    for (const Segment& s : segments) {
        std::vector<int> line{localOfCrackNode.at(s.a)};
        std::vector<int> walked(pathOf.at({s.a, s.b}));
        walked.push_back(localOfCrackNode.at(s.b));
        for (int v : walked) local.appendEdge(line.back(), v, line);
        for (std::size_t k = 0; k + 1 < line.size(); ++k)
            mouthEdge[{std::min(line[k], line[k + 1]), std::max(line[k], line[k + 1])}].insert(
                chainOfNode.at(s.a));
        cutPathOf[{s.a, s.b}] = std::vector<int>(line.begin() + 1, line.end() - 1);
    }
    // The sides of a chain, by orientation and connection: the two pieces along each of its mouth
    // edges take their sides from the sheet edge's direction (below), and each side spreads over
    // the pieces the chain's hats reach, across every edge but the chain's mouth edges (so a piece
    // that touches the mouth at a corner only gets its neighbours' side); a piece no side reaches
    // takes the side of the chain's nearest mouth point.
    std::map<std::pair<int, int>, std::vector<int>> piecesAtEdge;
    for (std::size_t i = 0; i < local.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const int a = local.triangles[i].corners[k], b = local.triangles[i].corners[(k + 1) % 3];
            piecesAtEdge[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(i));
        }
    auto centroidOf = [&](int i) {
        const auto& c = local.triangles[i].corners;
        return Eigen::Vector3d((local.vertices[c[0]].x + local.vertices[c[1]].x + local.vertices[c[2]].x) /
                               3.0);
    };
    std::map<int, std::vector<int>> supportOf;  // chain -> pieces with a corner carrying its hats
    for (std::size_t i = 0; i < local.triangles.size(); ++i) {
        std::set<int> chains;
        for (int v : local.triangles[i].corners)
            if (const MouthWeights* w = cornerWeights(v))
                for (const auto& nv : *w) chains.insert(chainOfNode.at(nv.first));
        for (int chain : chains) supportOf[chain].push_back(static_cast<int>(i));
    }
    std::vector<std::map<int, bool>> plus(local.triangles.size());  // piece -> chain -> on its + side
    for (const auto& [chain, support] : supportOf) {
        std::set<int> inSupport(support.begin(), support.end());
        auto isOwnMouth = [&](const std::pair<int, int>& e) {
            const auto it = mouthEdge.find(e);
            return it != mouthEdge.end() && it->second.count(chain) > 0;
        };
        // A sheet edge a -> b in its triangle's orientation has the triangle to its left seen along
        // n_c, inside the body, so n_c points to its left seen from outside: the surface piece
        // that runs along the path from a to b counter-clockwise (outward normal) is +.
        std::vector<int> queue;
        for (const Segment& seg : segments) {
            if (chainOfNode.at(seg.a) != chain) continue;
            std::vector<int> path{localOfCrackNode.at(seg.a)};
            const std::vector<int>& between = cutPathOf.at({seg.a, seg.b});
            path.insert(path.end(), between.begin(), between.end());
            path.push_back(localOfCrackNode.at(seg.b));
            for (std::size_t k = 0; k + 1 < path.size(); ++k) {
                const int u = path[k], w = path[k + 1];
                for (int i : piecesAtEdge.at({std::min(u, w), std::max(u, w)})) {
                    if (plus[i].count(chain)) continue;
                    const auto& c = local.triangles[i].corners;
                    bool forward = false;
                    for (int j = 0; j < 3; ++j) forward |= c[j] == u && c[(j + 1) % 3] == w;
                    plus[i][chain] = forward;
                    queue.push_back(i);
                }
            }
        }
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const int i = queue[head];
            const auto& c = local.triangles[i].corners;
            for (int k = 0; k < 3; ++k) {
                const std::pair<int, int> e{std::min(c[k], c[(k + 1) % 3]), std::max(c[k], c[(k + 1) % 3])};
                if (isOwnMouth(e)) continue;
                for (int j : piecesAtEdge.at(e))
                    if (j != i && inSupport.count(j) && !plus[j].count(chain)) {
                        plus[j][chain] = plus[i].at(chain);
                        queue.push_back(j);
                    }
            }
        }
        for (int i : support)
            if (!plus[i].count(chain)) plus[i][chain] = nearestMouth(centroidOf(i), chain).side > 0.0;
    }
    // A surface node off the mouth that has pieces on both sides of its chain (beyond the end of
    // the mouth, where the + and - sides meet without a mouth edge between them) keeps no plateau
    // value: the cut hats stay continuous there.
    {
        std::map<int, int> sides;  // surface node with a plateau -> bit 1: on a + piece, bit 2: on a - piece
        for (std::size_t i = 0; i < local.triangles.size(); ++i)
            for (int v : local.triangles[i].corners) {
                const Vertex& x = local.vertices[v];
                if (!x.weights.empty() || x.id >= n) continue;
                const auto it = extension.find(x.id);
                if (it == extension.end()) continue;
                sides[x.id] |= plus[i].at(chainOfNode.at(it->second.front().first)) ? 1 : 2;
            }
        for (const auto& [id, bits] : sides)
            if (bits == 3) extension.erase(id);
    }
    std::map<int, int> pieceCount;
    for (const auto& t : local.triangles) ++pieceCount[t.owner];
    for (std::size_t i = 0; i < local.triangles.size(); ++i) {
        const auto& t = local.triangles[i];
        bool weighted = false;
        for (int v : t.corners) weighted |= cornerWeights(v) != nullptr;
        if (!weighted && pieceCount[t.owner] == 1) continue;
        MouthPiece piece{panelOfCorners(local, t.corners, mesh.normal(t.owner)), {}};
        if (hasNoArea(piece.panel)) continue;
        piece.panel.normal = mesh.normal(t.owner);
        for (int k = 0; k < 3; ++k)
            if (const MouthWeights* w = cornerWeights(t.corners[k]))
                for (const auto& [node, value] : *w)
                    if (plus[i].at(chainOfNode.at(node))) piece.weights[k].emplace_back(node, value);
        out.surfacePieces[t.owner].push_back(std::move(piece));
    }
    // Surface triangles neither split nor carrying a cut hat need no pieces.
    for (auto it = out.surfacePieces.begin(); it != out.surfacePieces.end();) {
        bool carries = it->second.size() > 1;
        for (const MouthPiece& p : it->second)
            for (const auto& w : p.weights) carries |= !w.empty();
        it = carries ? std::next(it) : out.surfacePieces.erase(it);
    }

    // Crack triangles whose mouth edges pass through points of the cut: split there too.
    std::map<int, LocalMesh> crackSplits;
    for (const Segment& s : segments) {
        const std::vector<int>& path = cutPathOf.at({s.a, s.b});
        if (path.empty()) continue;
        LocalMesh& split = crackSplits[s.triangle];
        std::array<int, 3> corner;
        if (split.triangles.empty()) {
            for (int k = 0; k < 3; ++k) {
                const int node = cracks.triangle(s.triangle)[k];
                corner[k] =
                    split.addVertex({cracks.node(node), mouthIdOf(mesh, cracks, node), {{node, 1.0}}});
            }
            split.triangles.push_back({corner, s.triangle});
        }
        auto localOf = [&](int node) {
            for (int v = 0; v < 3; ++v)
                if (split.vertices[v].weights.front().first == node) return v;
            return -1;
        };
        int previous = localOf(s.a);
        const int end = localOf(s.b);
        const auto& corners = cracks.triangle(s.triangle);
        for (int v : path) {
            Vertex x = local.vertices[v];  // its crack hats: this triangle's corners only
            x.weights.erase(std::remove_if(x.weights.begin(), x.weights.end(),
                                           [&](const auto& nv) {
                                               return std::find(corners.begin(), corners.end(), nv.first) ==
                                                      corners.end();
                                           }),
                            x.weights.end());
            previous = split.splitEdge(previous, end, std::move(x));
        }
    }
    for (const auto& [t, split] : crackSplits)
        for (const auto& piece : split.triangles) {
            MouthPiece p{panelOfCorners(split, piece.corners, -cracks.normal(t)), {}};
            if (hasNoArea(p.panel)) continue;
            for (int k = 0; k < 3; ++k) p.weights[k] = split.vertices[piece.corners[k]].weights;
            out.crackPieces[t].push_back(std::move(p));
        }
    return out;
}

}  // namespace btfracture
