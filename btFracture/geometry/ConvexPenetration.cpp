// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexPenetration.h>

#include <btFracture/core/Error.h>

#include <ccd/ccd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

static_assert(sizeof(ccd_real_t) == sizeof(double), "btFracture expects libccd built with CCD_DOUBLE");

struct CcdPolytope {
    const ConvexPolytope* shape;
    Eigen::Vector3d centre;
};

void support(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const auto& p = *static_cast<const CcdPolytope*>(object);
    const Eigen::Vector3d d(dir->v[0], dir->v[1], dir->v[2]);
    const auto& points = p.shape->points;
    std::size_t best = 0;
    double bestDot = points[0].dot(d);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double dot = points[i].dot(d);
        if (dot > bestDot) {
            bestDot = dot;
            best = i;
        }
    }
    Eigen::Vector3d s = points[best];
    const double n = d.norm();
    if (p.shape->margin > 0.0 && n > 0.0) s += p.shape->margin / n * d;
    ccdVec3Set(out, s.x(), s.y(), s.z());
}

void centre(const void* object, ccd_vec3_t* out) {
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

}  // namespace

Penetration convexPenetration(const ConvexPolytope& a, const ConvexPolytope& b) {
    const CcdPolytope pa = prepare(a, "a"), pb = prepare(b, "b");
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = support;
    ccd.support2 = support;
    ccd.center1 = centre;
    ccd.center2 = centre;
    // Tolerances relative to the operands' size (libccd's defaults are absolute, 1e-4).
    double scale = a.margin + b.margin;
    for (const ConvexPolytope* shape : {&a, &b})
        for (const auto& p : shape->points)
            scale = std::max(scale, (p - (shape == &a ? pa.centre : pb.centre)).norm());
    ccd.max_iterations = 500;
    ccd.epa_tolerance = 1e-8 * scale;
    ccd.mpr_tolerance = 1e-8 * scale;
    ccd.dist_tolerance = 1e-10 * scale;
    ccd_real_t depth = 0;
    ccd_vec3_t dir, pos;
    Penetration result;
    if (ccdGJKPenetration(&pa, &pb, &ccd, &depth, &dir, &pos) != 0) return result;
    result.overlapping = true;
    result.depth = depth;
    result.direction = Eigen::Vector3d(dir.v[0], dir.v[1], dir.v[2]);
    const double n = result.direction.norm();
    if (n > 0.0) result.direction /= n;
    result.point = Eigen::Vector3d(pos.v[0], pos.v[1], pos.v[2]);
    return result;
}

}  // namespace btfracture
