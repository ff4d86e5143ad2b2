// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexClip.h>

#include <btFracture/core/Error.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace btfracture {

ConvexPolytope clipConvexPolytope(const ConvexPolytope& polytope, const Eigen::Vector3d& normal, double offset) {
    ConvexPolytope out;
    out.margin = polytope.margin;
    const double limit = offset - polytope.margin;
    std::vector<const Eigen::Vector3d*> dropped;
    for (const Eigen::Vector3d& p : polytope.points)
        if (normal.dot(p) <= limit)
            out.points.push_back(p);
        else
            dropped.push_back(&p);
    const std::size_t kept = out.points.size();
    for (std::size_t i = 0; i < kept; ++i)
        for (const Eigen::Vector3d* q : dropped) {
            const Eigen::Vector3d p = out.points[i];
            const double dp = normal.dot(p) - limit, dq = normal.dot(*q) - limit;  // dp <= 0 < dq
            out.points.push_back(p + (dp / (dp - dq)) * (*q - p));
        }
    // Only the hull's corners matter (and the crossings outnumber them).
    try {
        const TriangleMesh hull = convexHullMesh(out.points, "cut convex piece");
        std::vector<char> corner(hull.vertices.size(), 0);
        for (const auto& t : hull.triangles)
            for (int v : t) corner[v] = 1;
        std::vector<Eigen::Vector3d> corners;
        for (std::size_t v = 0; v < hull.vertices.size(); ++v)
            if (corner[v]) corners.push_back(hull.vertices[v]);
        out.points = std::move(corners);
    } catch (const Error&) {
        out.points.clear();  // flat: nothing with volume is left
    }
    return out;
}

double hullVolume(const ConvexPolytope& polytope) {
    try {
        const TriangleMesh hull = convexHullMesh(polytope.points, "convex piece");
        double six = 0.0;
        for (const auto& t : hull.triangles)
            six += hull.vertices[t[0]].dot(hull.vertices[t[1]].cross(hull.vertices[t[2]]));
        return six / 6.0;
    } catch (const Error&) {
        return 0.0;
    }
}

Eigen::Vector2d extentAlong(const ConvexPolytope& polytope, const Eigen::Vector3d& direction) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::Vector3d& p : polytope.points) {
        lo = std::min(lo, direction.dot(p));
        hi = std::max(hi, direction.dot(p));
    }
    return {lo - polytope.margin, hi + polytope.margin};
}

}  // namespace btfracture
