// SPDX-License-Identifier: Zlib
#pragma once
// A convex polytope (geometry/ConvexPenetration.h: the hull of its points inflated by its margin)
// cut by a plane: the part on the side n.x <= offset.
#include <btFracture/geometry/ConvexPenetration.h>

#include <Eigen/Core>

namespace btfracture {

struct ClippedPolytope {
    ConvexPolytope polytope;
    double volume = 0.0;  // of the hull of its points (margin not included) [m^3]; 0 when flat
};

// The cut hull is the hull of the hull's corners with n.x <= offset - margin and of the points
// where the hull's edges from those to the others cross that plane (every vertex of the cut hull
// is one of these); its corners are returned, with the cut hull's volume. The margin is kept, so
// the result's surface reaches at most to the plane n.x = offset. `normal` must be a unit vector.
// No points when what is left is flat or empty.
ClippedPolytope clipConvexPolytope(const ConvexPolytope& polytope, const Eigen::Vector3d& normal,
                                   double offset);

// Volume of the hull of the polytope's points (margin not included) [m^3]; 0 when flat.
double hullVolume(const ConvexPolytope& polytope);

// Extent of the polytope along the unit vector `direction`, margin included: [lowest, highest].
Eigen::Vector2d extentAlong(const ConvexPolytope& polytope, const Eigen::Vector3d& direction);

}  // namespace btfracture
