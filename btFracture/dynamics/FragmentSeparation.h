// SPDX-License-Identifier: Zlib
#pragma once
// Separates freshly spawned fragments whose collision shapes overlap (paper §5.2: fragments
// take the parent's place; overlapping shapes would make the replayed step push them apart
// violently, "popping"). Each overlap found by libccd (geometry/ConvexPenetration.h) is removed
// by translating the two fragments apart along the penetration direction, split in inverse
// proportion to their masses so that their common centre of mass does not move (unless one of
// them is blocked by static geometry, then the other moves alone). Positions only:
// the caller re-derives velocities from the parent's rigid motion.
#include <btFracture/geometry/ConvexPenetration.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

struct SeparationBody {
    std::vector<ConvexPolytope> pieces;  // convex collision pieces, world frame [m]
    double mass = 0.0;                   // [kg], > 0
    double length = 0.0;                 // characteristic length [m], > 0
    // Unit normals of static contacts (ground, walls), pointing into the body: it is never
    // pushed against them; the other body of an overlap then takes the whole push.
    std::vector<Eigen::Vector3d> blockedDirections;
};

struct SeparationOptions {
    int maxSweeps = 8;             // passes over all pairs
    double tolerance = 1e-6;       // overlaps below tolerance * min length are left alone
    double maxPushFraction = 0.1;  // a body moves at most this fraction of its length (logged)
};

struct SeparationResult {
    std::vector<Eigen::Vector3d> pushes;  // translation per body [m]
    double largestPush = 0.0;             // [m]
    double remainingDepth = 0.0;          // deepest overlap seen in the last sweep [m]
    int overlapsResolved = 0;
};

SeparationResult separateOverlaps(const std::vector<SeparationBody>& bodies,
                                  const SeparationOptions& options = {});

}  // namespace btfracture
