// SPDX-License-Identifier: Zlib
#pragma once
// Penetration depth between two convex polytopes (libccd, double precision), used to separate
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

// GJK + EPA (libccd ccdGJKPenetration): the minimal translation, to a tolerance of 1e-8 of the
// operands' size. (MPR, libccd's other method, measures along the line between the centres and
// overestimates badly for thin neighbours that share a face, which fragments do.) Throws
// btfracture::Error when an operand has no points, a non-finite point or a negative margin.
Penetration convexPenetration(const ConvexPolytope& a, const ConvexPolytope& b);

}  // namespace btfracture
