// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexPenetration.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/geometry/ConvexHull.h>

#include <ccd/ccd.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

namespace btfracture {
namespace {

static_assert(sizeof(ccd_real_t) == sizeof(double), "btFracture expects libccd built with CCD_DOUBLE");

constexpr int kGjkIterations = 128;
constexpr int kEpaIterations = 256;

// The point of `points` farthest along d (the first of equals: deterministic).
const Eigen::Vector3d& extreme(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& d) {
    std::size_t best = 0;
    double bestDot = points[0].dot(d);
    for (std::size_t i = 1; i < points.size(); ++i)
        if (const double dot = points[i].dot(d); dot > bestDot) {
            bestDot = dot;
            best = i;
        }
    return points[best];
}

// The bare polytopes' configuration space obstacle A - B.
struct Difference {
    const ConvexPolytope& a;
    const ConvexPolytope& b;
    Eigen::Vector3d support(const Eigen::Vector3d& d) const {
        return extreme(a.points, d) - extreme(b.points, -d);
    }
};

// libccd's view of a polytope inflated by its margin (the overlap test).
struct CcdPolytope {
    const ConvexPolytope* shape;
    Eigen::Vector3d centre;
};

void ccdSupport(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const auto& p = *static_cast<const CcdPolytope*>(object);
    const Eigen::Vector3d d(dir->v[0], dir->v[1], dir->v[2]);
    Eigen::Vector3d s = extreme(p.shape->points, d);
    const double n = d.norm();
    if (p.shape->margin > 0.0 && n > 0.0) s += p.shape->margin / n * d;
    ccdVec3Set(out, s.x(), s.y(), s.z());
}

void ccdCentre(const void* object, ccd_vec3_t* out) {
    const auto& c = static_cast<const CcdPolytope*>(object)->centre;
    ccdVec3Set(out, c.x(), c.y(), c.z());
}

CcdPolytope prepare(const ConvexPolytope& shape, const char* which) {
    std::ostringstream problem;
    if (shape.points.empty()) problem << "convexPenetration: polytope " << which << " has no points";
    if (!(shape.margin >= 0.0) || !std::isfinite(shape.margin))
        problem << "convexPenetration: polytope " << which << " has margin " << shape.margin
                << " (need >= 0)";
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : shape.points) {
        if (!p.allFinite()) {
            problem << "convexPenetration: polytope " << which << " has a non-finite point";
            break;
        }
        sum += p;
    }
    if (problem.tellp() > 0) throw Error(problem.str());
    return {&shape, sum / static_cast<double>(shape.points.size())};
}

// Closest point to the origin of the simplex W (1-4 points); W keeps the points of the feature
// it lies on. Returns true when the origin is inside a tetrahedron W.
bool reduceSimplex(std::vector<Eigen::Vector3d>& w, Eigen::Vector3d& closest) {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    const auto onTriangle = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                std::vector<Eigen::Vector3d>& kept) {
        const TriangleClosestPoint t = closestPointAndFeature(o, a, b, c);
        switch (t.feature) {
            case TriangleFeature::Face:
                kept = {a, b, c};
                break;
            case TriangleFeature::EdgeAB:
                kept = {a, b};
                break;
            case TriangleFeature::EdgeBC:
                kept = {b, c};
                break;
            case TriangleFeature::EdgeCA:
                kept = {c, a};
                break;
            case TriangleFeature::VertexA:
                kept = {a};
                break;
            case TriangleFeature::VertexB:
                kept = {b};
                break;
            case TriangleFeature::VertexC:
                kept = {c};
                break;
        }
        return t.point;
    };
    if (w.size() == 1) {
        closest = w[0];
    } else if (w.size() == 2) {
        closest = closestPointOnSegment(o, w[0], w[1]);
        if (closest == w[0])
            w = {w[0]};
        else if (closest == w[1])
            w = {w[1]};
    } else if (w.size() == 3) {
        std::vector<Eigen::Vector3d> kept;
        closest = onTriangle(w[0], w[1], w[2], kept);
        w = std::move(kept);
    } else {
        // Inside when the origin is on the inner side of every face (the face's plane does not
        // separate it from the opposite corner).
        static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
        double best = std::numeric_limits<double>::infinity();
        std::vector<Eigen::Vector3d> bestKept;
        bool inside = true;
        for (const auto& f : kFaces) {
            const Eigen::Vector3d& a = w[f[0]];
            const Eigen::Vector3d n = (w[f[1]] - a).cross(w[f[2]] - a);
            const double sideOrigin = n.dot(o - a), sideOpposite = n.dot(w[f[3]] - a);
            if (sideOrigin * sideOpposite > 0.0 || sideOrigin == 0.0) continue;
            inside = false;
            std::vector<Eigen::Vector3d> kept;
            const Eigen::Vector3d p = onTriangle(a, w[f[1]], w[f[2]], kept);
            if (p.squaredNorm() < best) {
                best = p.squaredNorm();
                closest = p;
                bestKept = std::move(kept);
            }
        }
        if (inside) {
            closest.setZero();
            return true;
        }
        w = std::move(bestKept);
    }
    return false;
}

// GJK (Gilbert, Johnson & Keerthi 1988) on the bare polytopes: the point of A - B closest to the
// origin (zero when A and B overlap) and the support points met on the way.
struct GjkResult {
    bool overlapping = false;
    Eigen::Vector3d closest = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> simplex;
};

GjkResult gjk(const Difference& cso, double scale) {
    GjkResult r;
    const double tiny = 1e-24 * scale * scale;
    Eigen::Vector3d v = cso.support(Eigen::Vector3d::UnitX());
    std::vector<Eigen::Vector3d> w = {v};
    for (int iteration = 0; iteration < kGjkIterations; ++iteration) {
        if (v.squaredNorm() <= tiny) {
            r.overlapping = true;
            break;
        }
        const Eigen::Vector3d s = cso.support(-v);
        // No point of A - B lies nearer the origin along v than v itself (up to rounding).
        if (v.squaredNorm() - v.dot(s) <= 1e-12 * v.squaredNorm()) break;
        if (std::find(w.begin(), w.end(), s) != w.end()) break;
        w.push_back(s);
        if (reduceSimplex(w, v)) {
            r.overlapping = true;
            break;
        }
    }
    r.closest = v;
    r.simplex = std::move(w);
    return r;
}

// EPA (van den Bergen 2001) on the bare polytopes, the origin inside A - B: the face of A - B
// nearest the origin, expanded from the hull of `start` plus the supports along the axes.
// Returns (distance, outward unit normal).
std::pair<double, Eigen::Vector3d> epa(const Difference& cso, std::vector<Eigen::Vector3d> start,
                                       double scale) {
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {1.0, -1.0})
            start.push_back(cso.support(sign * Eigen::Vector3d::Unit(axis)));
    TriangleMesh hull;
    try {
        hull = convexHullMesh(start, "A - B");
    } catch (const Error&) {
        return {0.0, Eigen::Vector3d::Zero()};  // A - B spans no volume: flat operands touch
    }
    std::vector<Eigen::Vector3d> v = hull.vertices;
    struct Face {
        std::array<int, 3> c;
        Eigen::Vector3d n;
        double d;
    };
    std::vector<Face> faces;
    const auto makeFace = [&](int a, int b, int c, Face& f) {
        Eigen::Vector3d n = (v[b] - v[a]).cross(v[c] - v[a]);
        const double length = n.norm();
        if (!(length > 1e-30 * scale * scale)) return false;
        n /= length;
        f = {{a, b, c}, n, n.dot(v[a])};
        return true;
    };
    for (const auto& t : hull.triangles) {
        Face f;
        if (makeFace(t[0], t[1], t[2], f)) faces.push_back(f);
    }
    const double tolerance = 1e-10 * scale;
    const auto nearestFace = [&faces] {
        std::size_t nearest = 0;
        for (std::size_t i = 1; i < faces.size(); ++i)
            if (faces[i].d < faces[nearest].d) nearest = i;
        return faces[nearest];
    };
    for (int iteration = 0; iteration < kEpaIterations && !faces.empty(); ++iteration) {
        const Face f = nearestFace();
        const Eigen::Vector3d s = cso.support(f.n);
        if (f.n.dot(s) - f.d <= tolerance) break;
        // Replace the faces that see s by the fan from s over their horizon.
        v.push_back(s);
        const int si = static_cast<int>(v.size()) - 1;
        std::set<std::pair<int, int>> edges;  // directed edges of the visible faces
        std::vector<Face> kept;
        for (const Face& g : faces) {
            if (g.n.dot(s - v[g.c[0]]) > tolerance) {
                for (int k = 0; k < 3; ++k) edges.insert({g.c[k], g.c[(k + 1) % 3]});
            } else {
                kept.push_back(g);
            }
        }
        bool valid = true;
        for (const auto& edge : edges) {
            if (edges.count({edge.second, edge.first})) continue;  // inside the visible region
            Face g;
            if (!makeFace(edge.first, edge.second, si, g) || g.d < -tolerance) {
                valid = false;
                break;
            }
            kept.push_back(g);
        }
        if (!valid) break;  // a degenerate fan: the nearest face so far stands
        faces = std::move(kept);
    }
    if (faces.empty()) return {0.0, Eigen::Vector3d::Zero()};
    const Face f = nearestFace();
    return {std::max(0.0, f.d), f.n};
}

}  // namespace

Penetration convexPenetration(const ConvexPolytope& a, const ConvexPolytope& b) {
    const CcdPolytope pa = prepare(a, "a"), pb = prepare(b, "b");
    double scale = a.margin + b.margin;
    for (const ConvexPolytope* shape : {&a, &b})
        for (const auto& p : shape->points)
            scale = std::max(scale, (p - (shape == &a ? pa.centre : pb.centre)).norm());
    if (!(scale > 0.0)) scale = 1.0;
    // Do the inflated polytopes touch at all (libccd's GJK, bounded)?
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccdSupport;
    ccd.support2 = ccdSupport;
    ccd.center1 = ccdCentre;
    ccd.center2 = ccdCentre;
    ccd.max_iterations = kGjkIterations;
    Penetration result;
    if (!ccdGJKIntersect(&pa, &pb, &ccd)) return result;

    // The bare polytopes' distance or depth, then the margins: A + ball(ra) - (B + ball(rb)) is
    // (A - B) + ball(ra + rb), so the depth is the bare one plus ra + rb, or ra + rb less the
    // bare distance, along the same direction (B moves along it to separate).
    const Difference cso{a, b};
    const double margins = a.margin + b.margin;
    const GjkResult g = gjk(cso, scale);
    double depth = 0.0;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    if (g.overlapping) {
        const auto [bare, normal] = epa(cso, g.simplex, scale);
        depth = bare + margins;
        direction = normal;
    } else {
        const double distance = g.closest.norm();
        depth = margins - distance;
        if (distance > 0.0) direction = -g.closest / distance;
    }
    if (!(depth > 0.0) || direction.squaredNorm() == 0.0) return result;
    result.overlapping = true;
    result.depth = depth;
    result.direction = direction;
    // A point in the overlap: halfway between A's deepest point along the direction and B's.
    result.point = 0.5 * (extreme(a.points, direction) + extreme(b.points, -direction));
    return result;
}

}  // namespace btfracture
