// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/MeshDecimation.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace btfracture {
namespace {

using Quadric = Eigen::Matrix4d;

struct Candidate {  // small: the heap holds a few per edge
    double cost;
    int a, b;  // a < b
    int stampA, stampB;
};

struct LaterCandidate {  // min-heap on (cost, a, b): deterministic order
    bool operator()(const Candidate& x, const Candidate& y) const {
        if (x.cost != y.cost) return x.cost > y.cost;
        if (x.a != y.a) return x.a > y.a;
        return x.b > y.b;
    }
};

class Decimator {
public:
    explicit Decimator(const TriangleMesh& mesh)
        : position_(mesh.vertices),
          triangles_(mesh.triangles),
          triangleAlive_(mesh.triangles.size(), 1),
          incident_(mesh.vertices.size()),
          quadric_(mesh.vertices.size(), Quadric::Zero()),
          stamp_(mesh.vertices.size(), 0),
          vertexAlive_(mesh.vertices.size(), 1),
          mark_(mesh.vertices.size(), 0) {
        liveTriangles_ = static_cast<int>(triangles_.size());
        liveVertices_ = static_cast<int>(position_.size());
        double totalArea = 0.0;
        for (int t = 0; t < liveTriangles_; ++t) {
            const auto& tri = triangles_[t];
            for (int v : tri) incident_[v].push_back(t);
            const Eigen::Vector3d n2 = areaNormal(tri);
            const double area2 = n2.norm();
            totalArea += 0.5 * area2;
            if (area2 <= 0.0) continue;
            const Eigen::Vector3d n = n2 / area2;
            Eigen::Vector4d plane;
            plane << n, -n.dot(position_[tri[0]]);
            const Quadric k = (0.5 * area2) * (plane * plane.transpose());
            for (int v : tri) quadric_[v] += k;
        }
        const double meanArea = totalArea / std::max(1, liveTriangles_);
        lengthWeight_ = 1e-3 * meanArea;
        Eigen::Vector3d lo = position_.front(), hi = lo;
        for (const auto& p : position_) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        minArea2_ = 2e-10 * (hi - lo).squaredNorm();
    }

    void run(int targetTriangles) {
        Eigen::Vector3d target;
        for (int t = 0; t < static_cast<int>(triangles_.size()); ++t)
            for (int k = 0; k < 3; ++k) {
                const int a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
                // Each edge once (the other triangle has b -> a).
                if (a < b) heap_.push_back({plan(a, b, target), a, b, stamp_[a], stamp_[b]});
            }
        std::make_heap(heap_.begin(), heap_.end(), LaterCandidate());
        while (liveTriangles_ > targetTriangles && !heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), LaterCandidate());
            const Candidate c = heap_.back();
            heap_.pop_back();
            if (!vertexAlive_[c.a] || !vertexAlive_[c.b] || stamp_[c.a] != c.stampA ||
                stamp_[c.b] != c.stampB)
                continue;
            plan(c.a, c.b, target);
            if (!collapseAllowed(c.a, c.b, target)) continue;
            collapse(c.a, c.b, target);
        }
    }

    TriangleMesh result(const std::string& name) const {
        TriangleMesh out;
        out.name = name;
        for (int t = 0; t < static_cast<int>(triangles_.size()); ++t)
            if (triangleAlive_[t]) out.triangles.push_back(triangles_[t]);
        takeUsedVertices(out, position_.size(), [&](int v) { return position_[v]; });
        return out;
    }

    int liveTriangles() const { return liveTriangles_; }

private:
    Eigen::Vector3d areaNormal(const std::array<int, 3>& t) const {
        return (position_[t[1]] - position_[t[0]]).cross(position_[t[2]] - position_[t[0]]);
    }

    static double quadricError(const Quadric& q, const Eigen::Vector3d& p) {
        const Eigen::Vector4d h(p.x(), p.y(), p.z(), 1.0);
        return std::max(0.0, h.dot(q * h));
    }

    // Cost of collapsing edge ab and the position the merged vertex takes.
    double plan(int a, int b, Eigen::Vector3d& best) const {
        const Quadric q = quadric_[a] + quadric_[b];
        const Eigen::Vector3d pa = position_[a], pb = position_[b], mid = 0.5 * (pa + pb);
        // Minimiser of the quadric when well posed and near the edge; else the best of a, b, mid.
        best = mid;
        double bestError = quadricError(q, mid);
        // Cramer's rule; skipped when A is near singular (flat or ridge regions).
        const Eigen::Matrix3d A = q.topLeftCorner<3, 3>();
        const Eigen::Vector3d rhs = -q.topRightCorner<3, 1>();
        const Eigen::Vector3d c0 = A.col(1).cross(A.col(2)), c1 = A.col(2).cross(A.col(0)),
                              c2 = A.col(0).cross(A.col(1));
        const double det = A.col(0).dot(c0);
        const double scale = A.norm();
        if (std::abs(det) > 1e-9 * scale * scale * scale) {
            const Eigen::Vector3d x = Eigen::Vector3d(c0.dot(rhs), c1.dot(rhs), c2.dot(rhs)) / det;
            if (x.allFinite() && (x - mid).norm() <= (pb - pa).norm()) {
                best = x;
                bestError = quadricError(q, x);
            }
        }
        for (const Eigen::Vector3d& p : {pa, pb}) {
            const double e = quadricError(q, p);
            if (e < bestError) {
                bestError = e;
                best = p;
            }
        }
        return bestError + lengthWeight_ * (pb - pa).squaredNorm();
    }

    void push(int a, int b) {
        if (a > b) std::swap(a, b);
        Eigen::Vector3d target;
        heap_.push_back({plan(a, b, target), a, b, stamp_[a], stamp_[b]});
        std::push_heap(heap_.begin(), heap_.end(), LaterCandidate());
    }

    void neighbours(int v, std::vector<int>& out) const {
        out.clear();
        for (int t : incident_[v])
            for (int w : triangles_[t])
                if (w != v) out.push_back(w);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    bool collapseAllowed(int a, int b, const Eigen::Vector3d& target) {
        if (liveVertices_ <= 4) return false;
        // Link condition: a and b share exactly the two apexes of the triangles at edge ab.
        int shared = 0;
        for (int t : incident_[a]) {
            const auto& tri = triangles_[t];
            if (tri[0] == b || tri[1] == b || tri[2] == b) ++shared;
        }
        if (shared != 2) return false;
        ++markStamp_;
        for (int t : incident_[a])
            for (int w : triangles_[t]) mark_[w] = markStamp_;
        int common = 0;
        ++markStamp_;
        for (int t : incident_[b])
            for (int w : triangles_[t])
                if (w != a && w != b && mark_[w] == markStamp_ - 1) {
                    mark_[w] = markStamp_;  // count each common neighbour once
                    ++common;
                }
        if (common != 2) return false;
        // Geometry: the surviving triangles around a and b must keep their orientation and area.
        for (int v : {a, b})
            for (int t : incident_[v]) {
                std::array<int, 3> tri = triangles_[t];
                if (std::count(tri.begin(), tri.end(), a) + std::count(tri.begin(), tri.end(), b) == 2)
                    continue;
                const Eigen::Vector3d before = areaNormal(tri);
                for (int& w : tri)
                    if (w == a || w == b) w = -1;
                Eigen::Vector3d p[3];
                for (int k = 0; k < 3; ++k) p[k] = tri[k] < 0 ? target : position_[tri[k]];
                const Eigen::Vector3d after = (p[1] - p[0]).cross(p[2] - p[0]);
                const double afterNorm = after.norm();
                if (afterNorm < minArea2_) return false;
                if (after.dot(before) < 0.2 * afterNorm * before.norm()) return false;
            }
        return true;
    }

    void collapse(int a, int b, const Eigen::Vector3d& target) {
        for (int t : incident_[b]) {
            auto& tri = triangles_[t];
            if (tri[0] == a || tri[1] == a || tri[2] == a) {
                triangleAlive_[t] = 0;
                --liveTriangles_;
                for (int w : tri)
                    if (w != b) {
                        auto& list = incident_[w];
                        list.erase(std::remove(list.begin(), list.end(), t), list.end());
                    }
            } else {
                for (int& w : tri)
                    if (w == b) w = a;
                incident_[a].push_back(t);
            }
        }
        incident_[b].clear();
        vertexAlive_[b] = 0;
        --liveVertices_;
        position_[a] = target;
        quadric_[a] += quadric_[b];
        ++stamp_[a];
        ++stamp_[b];
        neighbours(a, ring_);
        for (int w : ring_) push(a, w);
    }

    std::vector<Eigen::Vector3d> position_;
    std::vector<std::array<int, 3>> triangles_;
    std::vector<char> triangleAlive_;
    std::vector<std::vector<int>> incident_;
    std::vector<Quadric> quadric_;
    std::vector<int> stamp_;
    std::vector<char> vertexAlive_;
    int liveTriangles_ = 0;
    int liveVertices_ = 0;
    double lengthWeight_ = 0.0;
    double minArea2_ = 0.0;
    std::vector<Candidate> heap_;  // min-heap (LaterCandidate), stale entries skipped by stamps
    std::vector<int> ring_;
    std::vector<int> mark_;
    int markStamp_ = 0;
};

}  // namespace

TriangleMesh decimateMesh(const TriangleMesh& closedMesh, int targetTriangles) {
    const std::string source = closedMesh.name.empty() ? std::string("<unnamed mesh>") : closedMesh.name;
    if (targetTriangles < 4)
        throw Error(source + ": decimation target must be >= 4 triangles, got " +
                    std::to_string(targetTriangles));
    if (static_cast<int>(closedMesh.triangles.size()) <= targetTriangles) return closedMesh;
    const int nv = static_cast<int>(closedMesh.vertices.size());
    for (const auto& t : closedMesh.triangles)
        for (int i : t)
            if (i < 0 || i >= nv)
                throw Error(source + ": decimation input has triangle index " + std::to_string(i) +
                            " outside [0, " + std::to_string(nv) + ")");
    Decimator decimator(closedMesh);
    decimator.run(targetTriangles);
    if (decimator.liveTriangles() > targetTriangles)
        logf(LogLevel::Info, source, ": decimation stopped at ", decimator.liveTriangles(),
             " triangles (target ", targetTriangles,
             "): no further collapse keeps the mesh manifold and unflipped");
    return decimator.result(closedMesh.name);
}

}  // namespace btfracture
