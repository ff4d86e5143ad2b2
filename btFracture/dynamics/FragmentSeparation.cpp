// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FragmentSeparation.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/geometry/ConvexClip.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

struct Sphere {
    Eigen::Vector3d centre;
    double radius;
};

Sphere boundingSphere(const SeparationBody& body) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    double margin = 0.0;
    for (const auto& piece : body.pieces) {
        for (const auto& p : piece.points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        margin = std::max(margin, piece.margin);
    }
    if (!(lo.array() <= hi.array()).all()) return {Eigen::Vector3d::Zero(), -1.0};
    return {0.5 * (lo + hi), 0.5 * (hi - lo).norm() + margin};
}

ConvexPolytope shifted(const ConvexPolytope& piece, const Eigen::Vector3d& offset) {
    ConvexPolytope out = piece;
    for (auto& p : out.points) p += offset;
    return out;
}

// Moving the body by `push` would drive it into static geometry it touches.
bool blockedAlong(const SeparationBody& body, const Eigen::Vector3d& push) {
    for (const auto& n : body.blockedDirections)
        if (push.dot(n) < -1e-9 * push.norm()) return true;
    return false;
}

}  // namespace

std::vector<Eigen::Vector3d> blockedNormals(const std::vector<StaticContact>& contacts,
                                            const std::vector<ConvexPolytope>& pieces, double length) {
    Eigen::AlignedBox3d box;
    for (const ConvexPolytope& piece : pieces)
        for (const Eigen::Vector3d& p : piece.points) box.extend(p);
    std::vector<Eigen::Vector3d> normals;
    for (const StaticContact& c : contacts)
        if (box.isEmpty() || std::any_of(c.points.begin(), c.points.end(), [&](const Eigen::Vector3d& p) {
                return box.exteriorDistance(p) <= kStaticContactReach * length;
            }))
            normals.push_back(c.normal);
    return normals;
}

SeparationResult separateOverlaps(const std::vector<SeparationBody>& bodies,
                                  const SeparationOptions& options) {
    const std::size_t n = bodies.size();
    SeparationResult result;
    result.pushes.assign(n, Eigen::Vector3d::Zero());
    std::vector<Sphere> spheres(n);
    for (std::size_t i = 0; i < n; ++i) spheres[i] = boundingSphere(bodies[i]);
    std::vector<char> capped(n, 0);

    for (int sweep = 0; sweep < options.maxSweeps; ++sweep) {
        bool moved = false;
        result.remainingDepth = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                if (spheres[i].radius < 0.0 || spheres[j].radius < 0.0) continue;
                const Eigen::Vector3d ci = spheres[i].centre + result.pushes[i];
                const Eigen::Vector3d cj = spheres[j].centre + result.pushes[j];
                if ((ci - cj).norm() > spheres[i].radius + spheres[j].radius) continue;
                const double tolerance = options.tolerance * std::min(bodies[i].length, bodies[j].length);
                for (const auto& a : bodies[i].pieces)
                    for (const auto& b : bodies[j].pieces) {
                        const Penetration pen =
                            convexPenetration(shifted(a, result.pushes[i]), shifted(b, result.pushes[j]));
                        if (!pen.overlapping || pen.depth <= tolerance) continue;
                        result.remainingDepth = std::max(result.remainingDepth, pen.depth);
                        logf(LogLevel::Debug, "fragment separation: bodies ", i, " and ", j, " overlap by ",
                             pen.depth, " m along (", pen.direction.transpose(), ")");
                        const bool freeI = !capped[i] && !blockedAlong(bodies[i], -pen.direction);
                        const bool freeJ = !capped[j] && !blockedAlong(bodies[j], pen.direction);
                        if (!freeI && !freeJ) continue;
                        const double mi = bodies[i].mass, mj = bodies[j].mass;
                        // Both move when free; a capped or blocked body stays, the other takes the
                        // whole push.
                        double shareI = freeI ? mj / (mi + mj) : 0.0;
                        double shareJ = freeJ ? mi / (mi + mj) : 0.0;
                        const double total = shareI + shareJ;
                        shareI /= total;
                        shareJ /= total;
                        result.pushes[i] -= shareI * pen.depth * pen.direction;
                        result.pushes[j] += shareJ * pen.depth * pen.direction;
                        ++result.overlapsResolved;
                        moved = true;
                        for (std::size_t k : {i, j})
                            if (!capped[k] &&
                                result.pushes[k].norm() > options.maxPushFraction * bodies[k].length) {
                                result.pushes[k] *=
                                    options.maxPushFraction * bodies[k].length / result.pushes[k].norm();
                                capped[k] = 1;
                                logf(LogLevel::Debug, "fragment separation: body ", k, " needs more than ",
                                     options.maxPushFraction, " of its size (", bodies[k].length,
                                     " m) to clear its overlaps; push capped");
                            }
                    }
            }
        if (!moved) break;
    }
    for (const auto& p : result.pushes) result.largestPush = std::max(result.largestPush, p.norm());
    const auto cappedCount = std::count(capped.begin(), capped.end(), char(1));
    if (cappedCount > 0)
        logf(LogLevel::Warning, "fragment separation: ", cappedCount, " of ", bodies.size(),
             " fragments need more than ", options.maxPushFraction,
             " of their size to clear their overlaps; pushes capped there, the rest is left to the solver");
    return result;
}

bool containWithin(SeparationBody& body, const std::vector<ConvexPolytope>& container) {
    std::vector<Eigen::Vector3d> points;
    double margin = 0.0;
    for (const ConvexPolytope& piece : container) {
        points.insert(points.end(), piece.points.begin(), piece.points.end());
        margin = std::max(margin, piece.margin);
    }
    TriangleMesh hull;
    try {
        hull = convexHullMesh(points, "parent collision shape");
    } catch (const Error&) {
        return false;  // no volume to contain anything in
    }
    const double tolerance = std::max(0.1 * margin, 1e-6 * body.length);
    bool changed = false;
    for (ConvexPolytope& piece : body.pieces) {
        ConvexPolytope cut = piece;
        for (const auto& t : hull.triangles) {
            const Eigen::Vector3d& a = hull.vertices[t[0]];
            const Eigen::Vector3d n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a);
            if (!(n.norm() > 0.0)) continue;
            const Eigen::Vector3d unit = n.normalized();
            const double offset = unit.dot(a) + margin;
            // Pieces that reach past a face by less than a tenth of the margin (the shapes' single-
            // precision rounding is of that order) are left alone.
            if (extentAlong(cut, unit)[1] <= offset + tolerance) continue;
            cut = clipConvexPolytope(cut, unit, offset).polytope;
            if (cut.points.size() < 4) break;
        }
        if (cut.points.size() < 4 || cut.points == piece.points) continue;
        piece = std::move(cut);
        changed = true;
    }
    return changed;
}

TrimResult trimOverlaps(std::vector<SeparationBody>& bodies, const TrimOptions& options) {
    const std::size_t n = bodies.size();
    TrimResult result;
    result.changed.assign(n, 0);
    std::vector<std::vector<double>> volume(n);  // each piece's hull volume now
    std::vector<std::vector<double>> floor(n);   // smallest hull volume each piece may be cut to
    for (std::size_t i = 0; i < n; ++i)
        for (const ConvexPolytope& piece : bodies[i].pieces) {
            volume[i].push_back(hullVolume(piece));
            floor[i].push_back(options.keepVolumeFraction * volume[i].back());
        }
    for (int sweep = 0; sweep < options.maxSweeps; ++sweep) {
        bool cut = false;
        result.declined = 0;
        std::vector<Sphere> spheres(n);
        for (std::size_t i = 0; i < n; ++i) spheres[i] = boundingSphere(bodies[i]);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                if (spheres[i].radius < 0.0 || spheres[j].radius < 0.0) continue;
                if ((spheres[i].centre - spheres[j].centre).norm() > spheres[i].radius + spheres[j].radius)
                    continue;
                const double tolerance = options.tolerance * std::min(bodies[i].length, bodies[j].length);
                const double mi = bodies[i].mass, mj = bodies[j].mass;
                for (std::size_t pa = 0; pa < bodies[i].pieces.size(); ++pa)
                    for (std::size_t pb = 0; pb < bodies[j].pieces.size(); ++pb) {
                        ConvexPolytope& a = bodies[i].pieces[pa];
                        ConvexPolytope& b = bodies[j].pieces[pb];
                        const Penetration pen = convexPenetration(a, b);
                        if (!pen.overlapping || pen.depth <= tolerance) continue;
                        // b lies ahead of a along d: a keeps d.x <= c, b keeps d.x >= c.
                        const Eigen::Vector3d& d = pen.direction;
                        const Eigen::Vector2d ea = extentAlong(a, d), eb = extentAlong(b, d);
                        const double overlap = ea[1] - eb[0];
                        if (!(overlap > 0.0)) continue;
                        double shareA = (ea[1] - ea[0]) / ((ea[1] - ea[0]) + (eb[1] - eb[0]));
                        if (mi > options.heavyRatio * mj) shareA = 0.0;
                        if (mj > options.heavyRatio * mi) shareA = 1.0;
                        const double c = ea[1] - shareA * overlap;
                        ClippedPolytope cutA =
                            shareA > 0.0 ? clipConvexPolytope(a, d, c) : ClippedPolytope{a, volume[i][pa]};
                        ClippedPolytope cutB =
                            shareA < 1.0 ? clipConvexPolytope(b, -d, -c) : ClippedPolytope{b, volume[j][pb]};
                        if (cutA.volume < floor[i][pa] || cutB.volume < floor[j][pb] ||
                            cutA.polytope.points.size() < 4 || cutB.polytope.points.size() < 4) {
                            ++result.declined;
                            continue;
                        }
                        a = std::move(cutA.polytope);
                        b = std::move(cutB.polytope);
                        volume[i][pa] = cutA.volume;
                        volume[j][pb] = cutB.volume;
                        result.changed[i] = result.changed[j] = 1;
                        ++result.cuts;
                        cut = true;
                    }
            }
        if (!cut) break;
    }
    return result;
}

}  // namespace btfracture
