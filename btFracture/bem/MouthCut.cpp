// SPDX-License-Identifier: Zlib
#include <btFracture/bem/MouthCut.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
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

    int addVertex(Vertex v) {
        vertices.push_back(std::move(v));
        return static_cast<int>(vertices.size()) - 1;
    }
    // Splits every triangle with edge a-b at the new vertex.
    int splitEdge(int a, int b, Vertex v) {
        const int k = addVertex(std::move(v));
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
    // The nearest point of the mouth line (or of a crack node on the surface) to x: its distance,
    // the side of x (along the crack normal there) and the crack hats' trace there.
    struct NearestMouth {
        double distance = std::numeric_limits<double>::infinity();
        double side = 0.0;
        MouthWeights weights;
    };
    auto nearestMouth = [&](const Eigen::Vector3d& x) {
        NearestMouth best;
        for (const Segment& s : segments) {
            const Eigen::Vector3d c = closestPointOnSegment(x, cracks.node(s.a), cracks.node(s.b));
            const double d = (x - c).norm();
            if (d < best.distance)
                best = {d, (x - c).dot(cracks.normal(s.triangle)), weightsAlong(cracks, s.a, s.b, c)};
        }
        for (int i : surfaceNodes) {
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
    auto follow = [&](const Segment& s, std::vector<int>& path) {
        const int target = localOfCrackNode.at(s.b);
        const Eigen::Vector3d m = cracks.normal(s.triangle), origin = cracks.node(s.a);
        const double length = (cracks.node(s.b) - origin).norm();
        const double snap = 1e-6 * length + tolerance;
        int current = localOfCrackNode.at(s.a);
        // The plane meets the surface in a curve: leave the start toward the other node, then go
        // on the way the curve goes (it may turn round a corner of the body), never back.
        Eigen::Vector3d heading = (local.vertices[target].x - local.vertices[current].x).normalized();
        std::set<int> visited{current};
        for (int guard = 0; !local.hasEdge(current, target); ++guard) {
            if (guard > 1000 || current == target) return false;
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
            if (bestVertex < 0)
                bestVertex =
                    local.splitEdge(bestEdge[0], bestEdge[1],
                                    {bestPoint, nextId++, weightsAlong(cracks, s.a, s.b, bestPoint)});
            else if (local.vertices[bestVertex].weights.empty())
                local.vertices[bestVertex].weights =
                    weightsAlong(cracks, s.a, s.b, local.vertices[bestVertex].x);
            if (bestVertex != target) path.push_back(bestVertex);
            heading = (local.vertices[bestVertex].x - from).normalized();
            visited.insert(bestVertex);
            current = bestVertex;
        }
        return true;
    };
    // A mouth edge that cannot be followed over the surface (its crack plane does not lead from one
    // node to the other near the chord) is left out of the cut, counted; its nodes keep their
    // openings, whose cut hats then lack that edge's part.
    std::vector<Segment> followed;
    for (const Segment& s : segments) {
        const LocalMesh before = local;
        const int idBefore = nextId;
        std::vector<int> path;
        if (follow(s, path)) {
            pathOf[{s.a, s.b}] = path;
            followed.push_back(s);
            continue;
        }
        local = before;
        nextId = idBefore;
        ++out.unfollowedEdges;
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
    // Sides: a piece carries the cut hats when its centroid lies on the crack normal's side of
    // the nearest mouth point; its corners off the mouth carry the extension values.
    auto cornerWeights = [&](int v) -> const MouthWeights* {
        if (!local.vertices[v].weights.empty()) return &local.vertices[v].weights;
        const auto it = local.vertices[v].id < n ? extension.find(local.vertices[v].id) : extension.end();
        return it == extension.end() ? nullptr : &it->second;
    };
    // Mouth edges of the cut (local vertex pair -> the crack triangle whose edge it follows).
    std::map<std::pair<int, int>, int> mouthEdge;
    for (const Segment& s : segments) {
        std::vector<int> chain{localOfCrackNode.at(s.a)};
        const std::vector<int>& path = pathOf.at({s.a, s.b});
        chain.insert(chain.end(), path.begin(), path.end());
        chain.push_back(localOfCrackNode.at(s.b));
        for (std::size_t k = 0; k + 1 < chain.size(); ++k)
            mouthEdge[{std::min(chain[k], chain[k + 1]), std::max(chain[k], chain[k + 1])}] = s.triangle;
    }
    // The side of each piece: from the mouth edge it lies on, else from the nearest mouth point.
    std::vector<char> plus(local.triangles.size(), 0);
    for (std::size_t i = 0; i < local.triangles.size(); ++i) {
        const auto& c = local.triangles[i].corners;
        const Eigen::Vector3d centroid =
            (local.vertices[c[0]].x + local.vertices[c[1]].x + local.vertices[c[2]].x) / 3.0;
        double side = nearestMouth(centroid).side;
        for (int k = 0; k < 3; ++k) {
            const auto it = mouthEdge.find({std::min(c[k], c[(k + 1) % 3]), std::max(c[k], c[(k + 1) % 3])});
            if (it == mouthEdge.end()) continue;
            const Eigen::Vector3d on =
                closestPointOnSegment(centroid, local.vertices[c[k]].x, local.vertices[c[(k + 1) % 3]].x);
            side = (centroid - on).dot(cracks.normal(it->second));
            break;
        }
        plus[i] = side > 0.0;
    }
    // A surface node off the mouth that has pieces on both sides (beyond the end of the mouth, where
    // the + and - sides meet without a mouth edge between them) keeps no plateau value: the cut
    // hats stay continuous there.
    {
        std::map<int, int> sides;  // local vertex -> bit 1: on a + piece, bit 2: on a - piece
        for (std::size_t i = 0; i < local.triangles.size(); ++i)
            for (int v : local.triangles[i].corners) sides[v] |= plus[i] ? 1 : 2;
        for (const auto& [v, bits] : sides)
            if (bits == 3 && local.vertices[v].weights.empty() && local.vertices[v].id < n)
                extension.erase(local.vertices[v].id);
    }
    std::map<int, int> pieceCount;
    for (const auto& t : local.triangles) ++pieceCount[t.owner];
    for (std::size_t i = 0; i < local.triangles.size(); ++i) {
        const auto& t = local.triangles[i];
        bool weighted = false;
        for (int v : t.corners) weighted |= cornerWeights(v) != nullptr;
        if (!weighted && pieceCount[t.owner] == 1) continue;
        MouthPiece piece{panelOfCorners(local, t.corners, mesh.normal(t.owner)), {}};
        piece.panel.normal = mesh.normal(t.owner);
        if (weighted && plus[i])
            for (int k = 0; k < 3; ++k)
                if (const MouthWeights* w = cornerWeights(t.corners[k])) piece.weights[k] = *w;
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
        const std::vector<int>& path = pathOf.at({s.a, s.b});
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
        for (int v : path) previous = split.splitEdge(previous, end, local.vertices[v]);
    }
    for (const auto& [t, split] : crackSplits)
        for (const auto& piece : split.triangles) {
            MouthPiece p{panelOfCorners(split, piece.corners, -cracks.normal(t)), {}};
            for (int k = 0; k < 3; ++k) p.weights[k] = split.vertices[piece.corners[k]].weights;
            out.crackPieces[t].push_back(std::move(p));
        }
    return out;
}

}  // namespace btfracture
