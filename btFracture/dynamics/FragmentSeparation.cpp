// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FragmentSeparation.h>

#include <btFracture/core/Log.h>

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

}  // namespace btfracture
