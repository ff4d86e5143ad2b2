// SPDX-License-Identifier: Zlib
#pragma once
// Separates freshly spawned fragments whose collision shapes overlap (paper §5.2: fragments
// take the parent's place; overlapping shapes would make the replayed step push them apart
// violently, "popping"). Each overlap found by convexPenetration (geometry/ConvexPenetration.h) is removed
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

// A parent's solved contacts with static geometry sharing one unit normal (into the body), with
// their points on it (world frame [m]).
struct StaticContact {
    Eigen::Vector3d normal;
    std::vector<Eigen::Vector3d> points;
};

// The normals among the parent's static `contacts` that a fragment of characteristic length
// `length` [m] with world-frame convex `pieces` takes over as SeparationBody::blockedDirections:
// those with a point within kStaticContactReach * length of the pieces' bounding box. A fragment
// the parent's contact does not reach (the top of a standing column) may be pushed along its
// normal; one without convex pieces (a GImpact mesh) keeps every contact.
constexpr double kStaticContactReach = 0.05;
std::vector<Eigen::Vector3d> blockedNormals(const std::vector<StaticContact>& contacts,
                                            const std::vector<ConvexPolytope>& pieces, double length);

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

// Cuts every convex piece of `body` down to the convex hull of `container` (the parent's convex
// pieces, margins included): a fragment's collision shape then reaches nowhere its parent's did
// not, so it starts overlapping nothing (the ground, a neighbour) that its parent did not touch.
// A piece reaching past a face by less than a tenth of the container's margin, or that would keep
// no volume, is left as it is. Returns whether a piece changed.
bool containWithin(SeparationBody& body, const std::vector<ConvexPolytope>& container);

// Before any push: two overlapping convex pieces of different bodies are cut apart by a plane
// normal to their penetration direction instead of moving the bodies (moving a fragment up off
// a neighbour that rests on the ground raises the potential energy by m g times the overlap:
// energy the fracture would add). Each keeps its side of the plane, margins included, so the two
// touch. Bodies of similar mass share the overlap w in proportion to the pieces' extents along
// the normal; of a body more than heavyRatio times heavier than the other, nothing is cut (the
// lighter piece loses the whole overlap). No piece is cut below keepVolumeFraction of its
// original hull volume (a small piece inside a large one's hull, where a plane cannot stand for
// the crack between them): such overlaps are left to the push, which moves the lighter body.
struct TrimOptions {
    int maxSweeps = 4;
    double tolerance = 1e-6;          // overlaps below tolerance * min length are left alone
    double heavyRatio = 4.0;          // mass ratio above which only the lighter body is cut
    double keepVolumeFraction = 0.7;  // of a piece's original hull volume
};

struct TrimResult {
    std::vector<char> changed;  // per body: its pieces were cut
    int cuts = 0;               // pairs cut apart
    int declined = 0;           // overlapping pairs left to the push (cut too deep)
};

TrimResult trimOverlaps(std::vector<SeparationBody>& bodies, const TrimOptions& options = {});

}  // namespace btfracture
