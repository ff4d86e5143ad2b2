// SPDX-License-Identifier: Zlib
#include <btFracture/core/MeshCheck.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/SelfIntersection.h>
#include <btFracture/core/UnionFind.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>

namespace btfracture {
namespace {

void appendCount(std::ostringstream& out, int count, const char* singular, const char* plural) {
    if (count == 0) return;
    if (out.tellp() > 0) out << ", ";
    out << count << " " << (count == 1 ? singular : plural);
}

}  // namespace

bool MeshDefects::isClosedManifold() const {
    return invalidIndices == 0 && nonFiniteVertices == 0 && degenerateTriangles == 0 && boundaryEdges == 0 &&
           nonManifoldEdges == 0 && nonManifoldVertices == 0 && inconsistentEdges == 0;
}

bool MeshDefects::isClosedSolid() const {
    return isClosedManifold() && intersectingPairs == 0;
}

std::string MeshDefects::describe() const {
    std::ostringstream out;
    appendCount(out, invalidIndices, "invalid vertex index", "invalid vertex indices");
    appendCount(out, nonFiniteVertices, "non-finite vertex", "non-finite vertices");
    appendCount(out, degenerateTriangles, "degenerate triangle", "degenerate triangles");
    appendCount(out, boundaryEdges, "boundary edge (open mesh)", "boundary edges (open mesh)");
    appendCount(out, nonManifoldEdges, "non-manifold edge", "non-manifold edges");
    appendCount(out, nonManifoldVertices, "non-manifold vertex", "non-manifold vertices");
    appendCount(out, inconsistentEdges, "inconsistently oriented edge", "inconsistently oriented edges");
    appendCount(out, intersectingPairs, "self-intersecting triangle pair",
                "self-intersecting triangle pairs");
    return out.str();
}

MeshDefects inspectMesh(const TriangleMesh& mesh) {
    MeshDefects d;
    const int nv = static_cast<int>(mesh.vertices.size());
    for (const auto& v : mesh.vertices)
        if (!v.allFinite()) ++d.nonFiniteVertices;

    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
    for (const auto& v : mesh.vertices)
        if (v.allFinite()) {
            lo = lo.cwiseMin(v);
            hi = hi.cwiseMax(v);
        }
    const double diag2 = nv > 0 ? (hi - lo).squaredNorm() : 0.0;

    // Valid triangles only take part in the topological checks.
    std::vector<int> valid;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        const auto& tri = mesh.triangles[t];
        if (std::any_of(tri.begin(), tri.end(), [nv](int i) { return i < 0 || i >= nv; })) {
            ++d.invalidIndices;
            continue;
        }
        valid.push_back(t);
        const Eigen::Vector3d& a = mesh.vertices[tri[0]];
        const Eigen::Vector3d& b = mesh.vertices[tri[1]];
        const Eigen::Vector3d& c = mesh.vertices[tri[2]];
        if (!a.allFinite() || !b.allFinite() || !c.allFinite()) continue;  // counted as non-finite vertices
        const double area2 = (b - a).cross(c - a).norm();
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || !(area2 > 2e-12 * diag2))
            ++d.degenerateTriangles;
        d.signedVolume += a.dot(b.cross(c)) / 6.0;
    }

    // Every directed edge use, sorted so that the uses of one undirected edge are adjacent.
    struct EdgeUse {
        long long key;  // min * nv + max
        int triangle;
        bool forward;  // traversed from the smaller to the larger index
        bool operator<(const EdgeUse& o) const {
            return key < o.key || (key == o.key && triangle < o.triangle);
        }
    };
    std::vector<EdgeUse> uses;
    uses.reserve(3 * valid.size());
    for (int t : valid) {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            if (a == b) continue;
            uses.push_back({static_cast<long long>(std::min(a, b)) * nv + std::max(a, b), t, a < b});
        }
    }
    std::sort(uses.begin(), uses.end());
    UnionFind components(static_cast<int>(mesh.triangles.size()));
    for (size_t first = 0, last; first < uses.size(); first = last) {
        int forward = 0;
        for (last = first; last < uses.size() && uses[last].key == uses[first].key; ++last) {
            forward += uses[last].forward;
            components.unite(uses[first].triangle, uses[last].triangle);
        }
        const size_t n = last - first;
        if (n == 1) ++d.boundaryEdges;
        if (n > 2) ++d.nonManifoldEdges;
        if (n == 2 && forward != 1) ++d.inconsistentEdges;
    }
    std::vector<char> isRoot(mesh.triangles.size(), 0);
    for (int t : valid) isRoot[components.find(t)] = 1;
    d.components = static_cast<int>(std::count(isRoot.begin(), isRoot.end(), 1));

    // A manifold vertex has one edge-connected fan of triangles around it.
    std::vector<int> fanStart(nv + 1, 0), fanTriangles(3 * valid.size());
    for (int t : valid)
        for (int i : mesh.triangles[t]) ++fanStart[i + 1];
    std::partial_sum(fanStart.begin(), fanStart.end(), fanStart.begin());
    std::vector<int> fill(fanStart.begin(), fanStart.end() - 1);
    for (int t : valid)
        for (int i : mesh.triangles[t]) fanTriangles[fill[i]++] = t;
    std::vector<std::pair<int, int>> firstByOther;  // other endpoint of an edge at v -> fan index
    for (int v = 0; v < nv; ++v) {
        const int* fan = fanTriangles.data() + fanStart[v];
        const int size = fanStart[v + 1] - fanStart[v];
        if (size < 2) continue;
        UnionFind local(size);
        firstByOther.clear();
        for (int i = 0; i < size; ++i)
            for (int w : mesh.triangles[fan[i]]) {
                if (w == v) continue;
                auto it = std::find_if(firstByOther.begin(), firstByOther.end(),
                                       [w](const std::pair<int, int>& p) { return p.first == w; });
                if (it == firstByOther.end())
                    firstByOther.emplace_back(w, i);
                else
                    local.unite(i, it->second);
            }
        int roots = 0;
        for (int i = 0; i < size; ++i)
            if (local.find(i) == i) ++roots;
        if (roots > 1) ++d.nonManifoldVertices;
    }
    d.intersectingPairs = static_cast<int>(findSelfIntersections(mesh).size());
    return d;
}

MeshDefects requireClosedSolid(TriangleMesh& mesh) {
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (mesh.triangles.empty()) throw Error(source + ": mesh has no triangles");
    const MeshDefects d = inspectMesh(mesh);
    if (!d.isClosedSolid())
        throw Error(source +
                    ": not a closed, consistently oriented, non-self-intersecting manifold triangle mesh: " +
                    d.describe());
    if (d.signedVolume < 0.0) {
        for (auto& tri : mesh.triangles) std::swap(tri[1], tri[2]);
        logf(LogLevel::Warning, source, ": mesh was inside-out (signed volume ", d.signedVolume,
             "); flipped all ", mesh.triangles.size(), " triangles to face outward");
    }
    return d;
}

}  // namespace btfracture
