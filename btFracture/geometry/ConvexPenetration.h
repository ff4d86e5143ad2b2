// SPDX-License-Identifier: Zlib
#pragma once
// Penetration depth between two convex polytopes (double precision), used to separate
// freshly spawned fragment hulls before the replayed step (paper §5.2).
#include <Eigen/Core>

#include <vector>

namespace btfracture {

// A convex polytope given by its points (any points; only their convex hull matters) inflated
// by a margin [m] (Bullet's collision margin: the shape is hull + ball of radius margin).
struct ConvexPolytope {
    std::vector<Eigen::Vector3d> points;  // [m], a common frame for both operands
    double margin = 0.0;                  // [m], >= 0
};

struct Penetration {
    bool overlapping = false;
    double depth = 0.0;  // [m]; translating b by depth * direction makes the two touch
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit vector
    Eigen::Vector3d point = Eigen::Vector3d::Zero();      // a point in the overlap [m]
};

// The minimal translation, to about 1e-10 of the operands' size: libccd's GJK tells whether the
// inflated polytopes touch; then GJK and EPA (bounded: at most 128 and 256 iterations) on the
// bare polytopes give their distance or depth, and the margins add to it exactly (A + ball(ra)
// - (B + ball(rb)) is (A - B) + ball(ra + rb)). Not libccd's EPA: on fragments' pieces it can
// loop for ever (danfis/libccd#7; `falling_boxes` hung in it). Deterministic. Throws
// btfracture::Error when an operand has no points, a non-finite point or a negative margin.
Penetration convexPenetration(const ConvexPolytope& a, const ConvexPolytope& b);

}  // namespace btfracture
