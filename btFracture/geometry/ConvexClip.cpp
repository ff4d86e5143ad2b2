// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexClip.h>

#include <btFracture/core/Error.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace btfracture {
namespace {

double closedMeshVolume(const TriangleMesh& mesh) {
    double six = 0.0;
    for (const auto& t : mesh.triangles)
        six += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    return six / 6.0;
}

}  // namespace

ClippedPolytope clipConvexPolytope(const ConvexPolytope& polytope, const Eigen::Vector3d& normal,
                                   double offset) {
    ClippedPolytope clipped;
    ConvexPolytope& out = clipped.polytope;
    out.margin = polytope.margin;
    TriangleMesh hull;
    try {
        hull = convexHullMesh(polytope.points, "convex piece");
    } catch (const Error&) {
        return clipped;  // flat: nothing with volume to cut
    }
    const double limit = offset - polytope.margin;
    std::vector<char> kept(hull.vertices.size());
    for (std::size_t v = 0; v < hull.vertices.size(); ++v) {
        kept[v] = normal.dot(hull.vertices[v]) <= limit;
        if (kept[v]) out.points.push_back(hull.vertices[v]);
    }
    const std::size_t keptCount = out.points.size();
    if (keptCount == hull.vertices.size()) {
        clipped.volume = closedMeshVolume(hull);
        out.points = std::move(hull.vertices);  // nothing cut: the corners
        return clipped;
    }
    if (keptCount == 0) return clipped;
    // Each hull edge from a kept corner p to a cut one q (a closed mesh has each edge once in
    // that direction) crosses the plane once.
    for (const auto& t : hull.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& p = hull.vertices[t[k]];
            const Eigen::Vector3d& q = hull.vertices[t[(k + 1) % 3]];
            if (!kept[t[k]] || kept[t[(k + 1) % 3]]) continue;
            const double dp = normal.dot(p) - limit, dq = normal.dot(q) - limit;  // dp <= 0 < dq
            out.points.push_back(p + (dp / (dp - dq)) * (q - p));
        }
    // Only the cut hull's corners matter.
    try {
        TriangleMesh cut = convexHullMesh(out.points, "cut convex piece");
        clipped.volume = closedMeshVolume(cut);
        out.points = std::move(cut.vertices);
    } catch (const Error&) {
        out.points.clear();  // flat: nothing with volume is left
    }
    return clipped;
}

double hullVolume(const ConvexPolytope& polytope) {
    return convexHullVolume(polytope.points, "convex piece");
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
