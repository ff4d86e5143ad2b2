// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/HalfEdgeMesh.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/geometry/MeshQuality.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace btfracture {

HalfEdgeMesh::HalfEdgeMesh(const TriangleMesh& mesh) {
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (mesh.triangles.empty()) throw Error(source + ": mesh has no triangles");
    const MeshDefects defects = inspectMesh(mesh);
    if (!defects.isClosedManifold())
        throw Error(source +
                    ": not a closed, consistently oriented manifold triangle mesh: " + defects.describe());

    // Keep only referenced vertices, in their original order.
    std::vector<int> newIndex(mesh.vertices.size(), -1);
    for (const auto& tri : mesh.triangles)
        for (int v : tri) newIndex[v] = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (newIndex[v] == 0) {
            newIndex[v] = static_cast<int>(position_.size());
            position_.push_back(mesh.vertices[v]);
        }
    outgoing_.assign(position_.size(), -1);
    liveVertices_ = static_cast<int>(position_.size());

    origin_.reserve(3 * mesh.triangles.size());
    for (const auto& tri : mesh.triangles) addFace(newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]);

    // Twins: the two halfedges of an undirected edge sort next to each other.
    std::vector<std::tuple<int, int, int>> edges;
    edges.reserve(origin_.size());
    for (int h = 0; h < halfedgeSlots(); ++h) {
        const int a = origin(h), b = target(h);
        edges.emplace_back(std::min(a, b), std::max(a, b), h);
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i + 1 < edges.size(); i += 2)
        link(std::get<2>(edges[i]), std::get<2>(edges[i + 1]));
}

int HalfEdgeMesh::addFace(int a, int b, int c) {
    const int first = halfedgeSlots();
    for (int v : {a, b, c}) {
        origin_.push_back(v);
        twin_.push_back(-1);
    }
    outgoing_[a] = first;
    outgoing_[b] = first + 1;
    outgoing_[c] = first + 2;
    ++liveFaces_;
    return first / 3;
}

TriangleMesh HalfEdgeMesh::toTriangleMesh(const std::string& name) const {
    TriangleMesh out;
    out.name = name;
    std::vector<int> newIndex(position_.size(), -1);
    for (int v = 0; v < vertexSlots(); ++v)
        if (vertexAlive(v)) {
            newIndex[v] = static_cast<int>(out.vertices.size());
            out.vertices.push_back(position_[v]);
        }
    out.triangles.reserve(liveFaces_);
    for (int f = 0; f < faceSlots(); ++f)
        if (faceAlive(f)) {
            const auto tri = faceVertices(f);
            out.triangles.push_back({newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]});
        }
    return out;
}

void HalfEdgeMesh::compact() {
    std::vector<int> newVertex(position_.size(), -1);
    std::vector<Eigen::Vector3d> positions;
    positions.reserve(liveVertices_);
    for (int v = 0; v < vertexSlots(); ++v)
        if (vertexAlive(v)) {
            newVertex[v] = static_cast<int>(positions.size());
            positions.push_back(position_[v]);
        }
    std::vector<int> newFace(faceSlots(), -1);
    int faces = 0;
    for (int f = 0; f < faceSlots(); ++f)
        if (faceAlive(f)) newFace[f] = faces++;
    auto newHalfedge = [&](int h) { return 3 * newFace[face(h)] + h % 3; };

    std::vector<int> origins(3 * faces), twins(3 * faces);
    for (int h = 0; h < halfedgeSlots(); ++h)
        if (halfedgeAlive(h)) {
            origins[newHalfedge(h)] = newVertex[origin_[h]];
            twins[newHalfedge(h)] = newHalfedge(twin_[h]);
        }
    std::vector<int> outgoing(positions.size(), -1);
    for (int v = 0; v < vertexSlots(); ++v)
        if (vertexAlive(v)) outgoing[newVertex[v]] = newHalfedge(outgoing_[v]);

    position_ = std::move(positions);
    outgoing_ = std::move(outgoing);
    origin_ = std::move(origins);
    twin_ = std::move(twins);
}

void HalfEdgeMesh::throwOpenRing(int v) const {
    throw Error("half-edge mesh: the ring of halfedges around vertex " + std::to_string(v) +
                " does not close (connectivity corrupted by an edit)");
}

int HalfEdgeMesh::valence(int v) const {
    int n = 0;
    forEachOutgoing(v, [&](int) { ++n; });
    return n;
}

Eigen::Vector3d HalfEdgeMesh::faceAreaNormal(int f) const {
    const auto tri = faceVertices(f);
    return (position_[tri[1]] - position_[tri[0]]).cross(position_[tri[2]] - position_[tri[0]]);
}

Eigen::Vector3d HalfEdgeMesh::vertexNormal(int v) const {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    forEachOutgoing(v, [&](int h) { n += faceAreaNormal(face(h)); });
    const double length = n.norm();
    return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

double HalfEdgeMesh::faceMinAngle(int f) const {
    const auto tri = faceVertices(f);
    return triangleMinAngle(position_[tri[0]], position_[tri[1]], position_[tri[2]]);
}

double HalfEdgeMesh::minAngleAroundVertex(int v) const {
    double smallest = M_PI;
    forEachOutgoing(v, [&](int h) { smallest = std::min(smallest, faceMinAngle(face(h))); });
    return smallest;
}

double HalfEdgeMesh::minAngleAroundEdge(int h) const {
    return std::min(minAngleAroundVertex(origin(h)), minAngleAroundVertex(target(h)));
}

bool HalfEdgeMesh::adjacent(int u, int v) const {
    bool found = false;
    forEachOutgoing(u, [&](int h) { found = found || target(h) == v; });
    return found;
}

bool HalfEdgeMesh::collapseKeepsManifold(int h) const {
    if (liveVertices_ <= 4) return false;
    // The two apexes lose a neighbour: at valence 3 they would be left with two faces back to
    // back (a tetrahedron among other components passes the link condition and the count).
    if (valence(apex(h)) <= 3 || valence(apex(twin(h))) <= 3) return false;
    const int a = origin(h), b = target(h);
    int shared = 0;
    forEachOutgoing(a, [&](int g) {
        if (adjacent(b, target(g))) ++shared;
    });
    return shared == 2;
}

namespace {

double unitCosine(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    const double lengths = u.norm() * v.norm();
    return lengths > 0.0 ? u.dot(v) / lengths : -1.0;
}

}  // namespace

HalfEdgeMesh::EditPreview HalfEdgeMesh::previewCollapse(int h, const Eigen::Vector3d& p) const {
    EditPreview preview;
    preview.minAngle = M_PI;
    const Eigen::Vector3d& pa = position_[origin(h)];
    const Eigen::Vector3d& pb = position_[target(h)];
    double deviationA2 = INFINITY, deviationB2 = INFINITY;
    const int removed0 = face(h), removed1 = face(twin(h));
    for (int v : {origin(h), target(h)}) {
        forEachOutgoing(v, [&](int g) {
            const int f = face(g);
            if (f == removed0 || f == removed1) return;
            const Eigen::Vector3d& u = position_[target(g)];
            const Eigen::Vector3d& w = position_[apex(g)];
            preview.minAngle = std::min(preview.minAngle, triangleMinAngle(p, u, w));
            preview.maxEdgeLength = std::max(preview.maxEdgeLength, (u - p).norm());
            preview.minNormalCosine =
                std::min(preview.minNormalCosine, unitCosine((u - p).cross(w - p), faceAreaNormal(f)));
            deviationA2 = std::min(deviationA2, (closestPointOnTriangle(pa, p, u, w) - pa).squaredNorm());
            deviationB2 = std::min(deviationB2, (closestPointOnTriangle(pb, p, u, w) - pb).squaredNorm());
        });
    }
    preview.deviation = std::sqrt(std::max(deviationA2, deviationB2));
    return preview;
}

int HalfEdgeMesh::collapseEdge(int h, const Eigen::Vector3d& p) {
    const int t = twin(h);
    const int a = origin(h), b = target(h), c = apex(h), d = apex(t);
    const int x1 = twin(next(h)), x2 = twin(prev(h));  // c->b, a->c
    const int y1 = twin(next(t)), y2 = twin(prev(t));  // d->a, b->d
    std::vector<int> fromA;
    forEachOutgoing(a, [&](int g) { fromA.push_back(g); });
    for (int g : fromA) origin_[g] = b;
    link(x1, x2);
    link(y1, y2);
    outgoing_[b] = x2;
    outgoing_[c] = x1;
    outgoing_[d] = y1;
    outgoing_[a] = -1;
    for (int f : {face(h), face(t)})
        for (int k = 0; k < 3; ++k) origin_[3 * f + k] = twin_[3 * f + k] = -1;
    position_[b] = p;
    liveFaces_ -= 2;
    --liveVertices_;
    return b;
}

bool HalfEdgeMesh::flipKeepsManifold(int h) const {
    const int c = apex(h), d = apex(twin(h));
    return c != d && valence(origin(h)) > 3 && valence(target(h)) > 3 && !adjacent(c, d);
}

HalfEdgeMesh::EditPreview HalfEdgeMesh::previewFlip(int h) const {
    const Eigen::Vector3d& a = position_[origin(h)];
    const Eigen::Vector3d& b = position_[target(h)];
    const Eigen::Vector3d& c = position_[apex(h)];
    const Eigen::Vector3d& d = position_[apex(twin(h))];
    const Eigen::Vector3d n0 = faceAreaNormal(face(h)), n1 = faceAreaNormal(face(twin(h)));
    const Eigen::Vector3d m0 = (d - a).cross(c - a), m1 = (c - b).cross(d - b);
    EditPreview preview;
    preview.minAngle = std::min(triangleMinAngle(a, d, c), triangleMinAngle(b, c, d));
    preview.maxEdgeLength = (d - c).norm();
    preview.minNormalCosine =
        std::min({unitCosine(m0, n0), unitCosine(m0, n1), unitCosine(m1, n0), unitCosine(m1, n1)});
    const Eigen::Vector3d mid = 0.5 * (a + b);
    preview.deviation = std::sqrt(std::min((closestPointOnTriangle(mid, a, d, c) - mid).squaredNorm(),
                                           (closestPointOnTriangle(mid, b, c, d) - mid).squaredNorm()));
    return preview;
}

void HalfEdgeMesh::flipEdge(int h) {
    const int t = twin(h);
    const int h1 = next(h), h2 = prev(h), t1 = next(t), t2 = prev(t);
    const int a = origin(h), b = target(h), c = apex(h), d = apex(t);
    const int xbc = twin(h1), xca = twin(h2), xad = twin(t1), xdb = twin(t2);
    // Face of h becomes (a, d, c), face of t becomes (b, c, d).
    origin_[h] = a;
    origin_[h1] = d;
    origin_[h2] = c;
    origin_[t] = b;
    origin_[t1] = c;
    origin_[t2] = d;
    link(h, xad);
    link(h1, t1);
    link(h2, xca);
    link(t, xbc);
    link(t2, xdb);
    outgoing_[a] = h;
    outgoing_[b] = t;
    outgoing_[c] = h2;
    outgoing_[d] = t2;
}

int HalfEdgeMesh::splitEdge(int h, const Eigen::Vector3d& p) {
    const int t = twin(h);
    const int h1 = next(h), h2 = prev(h), t1 = next(t), t2 = prev(t);
    const int a = origin(h), b = target(h), c = apex(h), d = apex(t);
    const int xcb = twin(h1), xda = twin(t1);
    const int m = static_cast<int>(position_.size());
    position_.push_back(p);
    outgoing_.push_back(-1);
    ++liveVertices_;
    // Face of h becomes (a, m, c), face of t becomes (b, m, d); two new faces (m, b, c), (m, a, d).
    origin_[h1] = m;
    origin_[t1] = m;
    const int g = 3 * addFace(m, b, c);
    const int k = 3 * addFace(m, a, d);
    link(g + 1, xcb);
    link(g + 2, h1);
    link(k + 1, xda);
    link(k + 2, t1);
    link(h, k);
    link(t, g);
    outgoing_[m] = h1;
    outgoing_[a] = h;
    outgoing_[b] = t;
    outgoing_[c] = h2;
    outgoing_[d] = t2;
    return m;
}

}  // namespace btfracture
