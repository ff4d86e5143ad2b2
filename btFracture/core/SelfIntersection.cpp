// SPDX-License-Identifier: Zlib
#include <btFracture/core/SelfIntersection.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace btfracture {
namespace {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;

constexpr double kRelativeTolerance = 1e-12;

struct Triangle {
    std::array<Vec3, 3> p;
    Vec3 normal;   // unnormalised (b - a) x (c - a)
    double size;   // longest edge
    int dropAxis;  // coordinate dropped for 2D tests in the triangle's plane
};

Triangle makeTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    Triangle t{{a, b, c}, (b - a).cross(c - a), 0.0, 0};
    t.size = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    t.normal.cwiseAbs().maxCoeff(&t.dropAxis);
    return t;
}

Vec2 project(const Vec3& p, int dropAxis) {
    switch (dropAxis) {
        case 0:
            return {p.y(), p.z()};
        case 1:
            return {p.z(), p.x()};
        default:
            return {p.x(), p.y()};
    }
}

double snap(double value, double tolerance) {
    return std::abs(value) <= tolerance ? 0.0 : value;
}

double orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 u = b - a, v = c - a;
    return u.x() * v.y() - u.y() * v.x();
}

// Closed segments pq and rs in a plane; `area` is the tolerance for orientation values.
bool segmentsIntersect2d(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s, double area) {
    const double o1 = snap(orient2d(p, q, r), area), o2 = snap(orient2d(p, q, s), area);
    const double o3 = snap(orient2d(r, s, p), area), o4 = snap(orient2d(r, s, q), area);
    if (o1 * o2 > 0.0 || o3 * o4 > 0.0) return false;
    if (o1 != 0.0 || o2 != 0.0 || o3 != 0.0 || o4 != 0.0) return true;
    // Collinear: overlap of the projections on the segments' main direction.
    const Vec2 d = (q - p).cwiseAbs() + (s - r).cwiseAbs();
    const int k = d.x() >= d.y() ? 0 : 1;
    return std::max(std::min(p[k], q[k]), std::min(r[k], s[k])) <=
           std::min(std::max(p[k], q[k]), std::max(r[k], s[k]));
}

// Closed triangle abc contains p (either winding).
bool pointInTriangle2d(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, double area) {
    const double o1 = snap(orient2d(a, b, p), area), o2 = snap(orient2d(b, c, p), area),
                 o3 = snap(orient2d(c, a, p), area);
    const bool negative = o1 < 0.0 || o2 < 0.0 || o3 < 0.0;
    const bool positive = o1 > 0.0 || o2 > 0.0 || o3 > 0.0;
    return !(negative && positive);
}

bool coplanarTrianglesIntersect(const Triangle& s, const Triangle& t, double length) {
    const int axis = s.dropAxis;
    std::array<Vec2, 3> a, b;
    for (int k = 0; k < 3; ++k) {
        a[k] = project(s.p[k], axis);
        b[k] = project(t.p[k], axis);
    }
    const double area = kRelativeTolerance * length * length;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segmentsIntersect2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], area)) return true;
    return pointInTriangle2d(a[0], b[0], b[1], b[2], area) || pointInTriangle2d(b[0], a[0], a[1], a[2], area);
}

// Closed segment pq against closed triangle t.
bool segmentTriangleIntersect(const Vec3& p, const Vec3& q, const Triangle& t, double length) {
    const double tolerance = kRelativeTolerance * t.normal.norm() * length;
    const double dp = snap(t.normal.dot(p - t.p[0]), tolerance),
                 dq = snap(t.normal.dot(q - t.p[0]), tolerance);
    if (dp * dq > 0.0) return false;
    const double area = kRelativeTolerance * length * length;
    const Vec2 a = project(t.p[0], t.dropAxis), b = project(t.p[1], t.dropAxis),
               c = project(t.p[2], t.dropAxis);
    if (dp == 0.0 && dq == 0.0) {
        const Vec2 p2 = project(p, t.dropAxis), q2 = project(q, t.dropAxis);
        return segmentsIntersect2d(p2, q2, a, b, area) || segmentsIntersect2d(p2, q2, b, c, area) ||
               segmentsIntersect2d(p2, q2, c, a, area) || pointInTriangle2d(p2, a, b, c, area);
    }
    const Vec3 x = dp == 0.0 ? p : dq == 0.0 ? q : Vec3(p + (q - p) * (dp / (dp - dq)));
    return pointInTriangle2d(project(x, t.dropAxis), a, b, c, area);
}

// Range [lo, hi] of direction . x over the part of `t` on the other triangle's plane, given the
// snapped signed distances of t's corners to that plane (not all of one strict sign, not all 0).
std::pair<double, double> planeCrossing(const Triangle& t, const std::array<double, 3>& d,
                                        const Vec3& direction) {
    double lo = INFINITY, hi = -INFINITY;
    auto add = [&](const Vec3& x) {
        const double s = direction.dot(x);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    };
    for (int k = 0; k < 3; ++k) {
        const int l = (k + 1) % 3;
        if (d[k] == 0.0) add(t.p[k]);
        if ((d[k] > 0.0 && d[l] < 0.0) || (d[k] < 0.0 && d[l] > 0.0))
            add(t.p[k] + (t.p[l] - t.p[k]) * (d[k] / (d[k] - d[l])));
    }
    return {lo, hi};
}

// Two triangles without a shared vertex: both must cross the other's plane, and the two crossing
// intervals on the planes' intersection line must overlap.
bool disjointTrianglesIntersect(const Triangle& s, const Triangle& t) {
    const double length = std::max(s.size, t.size);
    std::array<double, 3> ds, dt;
    const double tolS = kRelativeTolerance * s.normal.norm() * length;
    const double tolT = kRelativeTolerance * t.normal.norm() * length;
    for (int k = 0; k < 3; ++k) {
        dt[k] = snap(s.normal.dot(t.p[k] - s.p[0]), tolS);
        ds[k] = snap(t.normal.dot(s.p[k] - t.p[0]), tolT);
    }
    auto oneSide = [](const std::array<double, 3>& d) {
        return (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) || (d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0);
    };
    if (oneSide(ds) || oneSide(dt)) return false;
    const Vec3 direction = s.normal.cross(t.normal);
    const bool allZero =
        (dt[0] == 0.0 && dt[1] == 0.0 && dt[2] == 0.0) || (ds[0] == 0.0 && ds[1] == 0.0 && ds[2] == 0.0);
    if (allZero || direction.norm() <= kRelativeTolerance * s.normal.norm() * t.normal.norm())
        return coplanarTrianglesIntersect(s, t, length);
    const auto [loS, hiS] = planeCrossing(s, ds, direction);
    const auto [loT, hiT] = planeCrossing(t, dt, direction);
    const double tolerance = kRelativeTolerance * direction.norm() * length;
    return loS <= hiT + tolerance && loT <= hiS + tolerance;
}

// Pair of mesh triangles, classified by how many vertex indices they share.
bool meshTrianglesIntersect(const TriangleMesh& mesh, const std::array<int, 3>& ia,
                            const std::array<int, 3>& ib, const Triangle& s, const Triangle& t) {
    int shared = 0, sharedA[3], sharedB[3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (ia[i] == ib[j]) {
                sharedA[shared] = i;
                sharedB[shared] = j;
                ++shared;
            }
    const double length = std::max(s.size, t.size);
    switch (shared) {
        case 0:
            return disjointTrianglesIntersect(s, t);
        case 1: {
            // The intersection is convex and contains the shared vertex; it holds more than that
            // vertex exactly when one triangle's opposite edge meets the other triangle.
            const int a = sharedA[0], b = sharedB[0];
            return segmentTriangleIntersect(s.p[(a + 1) % 3], s.p[(a + 2) % 3], t, length) ||
                   segmentTriangleIntersect(t.p[(b + 1) % 3], t.p[(b + 2) % 3], s, length);
        }
        case 2: {
            // Across a shared edge the triangles meet beyond it only when folded flat onto each other.
            const Vec3& u = mesh.vertices[ia[sharedA[0]]];
            const Vec3& v = mesh.vertices[ia[sharedA[1]]];
            const Vec3& apexS = s.p[3 - sharedA[0] - sharedA[1]];
            const Vec3& apexT = t.p[3 - sharedB[0] - sharedB[1]];
            const Vec3 nS = (v - u).cross(apexS - u), nT = (v - u).cross(apexT - u);
            const double offPlane = snap(nS.dot(apexT - u), kRelativeTolerance * nS.norm() * length);
            return offPlane == 0.0 && nS.dot(nT) > 0.0;
        }
        default:
            return true;  // the same three vertices twice
    }
}

// Axis-aligned bounding-box tree over triangles, median split on the longest axis.
class TriangleTree {
public:
    TriangleTree(const std::vector<Eigen::AlignedBox3d>& boxes, std::vector<int> ids)
        : boxes_(boxes), ids_(std::move(ids)) {
        if (!ids_.empty()) build(0, static_cast<int>(ids_.size()));
    }

    // Calls visit(i, j) once for every pair of triangles whose boxes overlap.
    template <class Visit>
    void forEachOverlappingPair(Visit&& visit) const {
        if (!nodes_.empty()) self(0, visit);
    }

private:
    static constexpr int kLeafSize = 4;
    struct Node {
        Eigen::AlignedBox3d box;
        int first, count;
        int left = -1, right = -1;
        bool leaf() const { return left < 0; }
    };

    int build(int first, int count) {
        const int index = static_cast<int>(nodes_.size());
        nodes_.push_back({Eigen::AlignedBox3d(), first, count});
        Eigen::AlignedBox3d box, centres;
        for (int i = first; i < first + count; ++i) {
            box.extend(boxes_[ids_[i]]);
            centres.extend(boxes_[ids_[i]].center());
        }
        nodes_[index].box = box;
        if (count <= kLeafSize) return index;
        int axis;
        centres.sizes().maxCoeff(&axis);
        const int middle = first + count / 2;
        std::nth_element(ids_.begin() + first, ids_.begin() + middle, ids_.begin() + first + count,
                         [&](int a, int b) {
                             const double ca = boxes_[a].center()[axis], cb = boxes_[b].center()[axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        const int left = build(first, middle - first);
        const int right = build(middle, first + count - middle);
        nodes_[index].left = left;
        nodes_[index].right = right;
        return index;
    }

    template <class Visit>
    void self(int n, Visit& visit) const {
        const Node& node = nodes_[n];
        if (node.leaf()) {
            for (int i = node.first; i < node.first + node.count; ++i)
                for (int j = i + 1; j < node.first + node.count; ++j)
                    visitIfOverlapping(ids_[i], ids_[j], visit);
            return;
        }
        self(node.left, visit);
        self(node.right, visit);
        cross(node.left, node.right, visit);
    }

    template <class Visit>
    void cross(int a, int b, Visit& visit) const {
        const Node& na = nodes_[a];
        const Node& nb = nodes_[b];
        if (!na.box.intersects(nb.box)) return;
        if (na.leaf() && nb.leaf()) {
            for (int i = na.first; i < na.first + na.count; ++i)
                for (int j = nb.first; j < nb.first + nb.count; ++j)
                    visitIfOverlapping(ids_[i], ids_[j], visit);
        } else if (na.leaf() || (!nb.leaf() && nb.count > na.count)) {
            cross(a, nb.left, visit);
            cross(a, nb.right, visit);
        } else {
            cross(na.left, b, visit);
            cross(na.right, b, visit);
        }
    }

    template <class Visit>
    void visitIfOverlapping(int i, int j, Visit& visit) const {
        if (boxes_[i].intersects(boxes_[j])) visit(std::min(i, j), std::max(i, j));
    }

    const std::vector<Eigen::AlignedBox3d>& boxes_;
    std::vector<int> ids_;
    std::vector<Node> nodes_;
};

}  // namespace

std::vector<std::pair<int, int>> findSelfIntersections(const TriangleMesh& mesh) {
    const int nv = static_cast<int>(mesh.vertices.size());
    const int nt = static_cast<int>(mesh.triangles.size());
    Eigen::AlignedBox3d bounds;
    for (const auto& v : mesh.vertices)
        if (v.allFinite()) bounds.extend(v);
    const double pad = bounds.isEmpty() ? 0.0 : kRelativeTolerance * bounds.diagonal().norm();

    std::vector<Triangle> triangles(nt);
    std::vector<Eigen::AlignedBox3d> boxes(nt);
    std::vector<int> usable;
    for (int t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        if (std::any_of(tri.begin(), tri.end(), [nv](int i) { return i < 0 || i >= nv; })) continue;
        // A repeated corner is degenerate whatever its coordinates; the area test below alone
        // misses it when the compiler fuses (b - a) x (c - a) into FMAs (found by fuzzing).
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
        const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
        if (!a.allFinite() || !b.allFinite() || !c.allFinite()) continue;
        triangles[t] = makeTriangle(a, b, c);
        if (!(triangles[t].normal.squaredNorm() > 0.0)) continue;
        boxes[t].extend(a).extend(b).extend(c);
        boxes[t].min().array() -= pad;
        boxes[t].max().array() += pad;
        usable.push_back(t);
    }

    std::vector<std::pair<int, int>> pairs;
    TriangleTree(boxes, std::move(usable)).forEachOverlappingPair([&](int i, int j) {
        if (meshTrianglesIntersect(mesh, mesh.triangles[i], mesh.triangles[j], triangles[i], triangles[j]))
            pairs.emplace_back(i, j);
    });
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace btfracture
