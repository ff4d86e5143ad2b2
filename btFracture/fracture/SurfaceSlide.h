// SPDX-License-Identifier: Zlib
#pragma once
// Where a crack front meets the body's surface it slides along it (CrackGrowth for the coarse
// BEM front, CrackFront for the voxel-resolution markers): the front stops just inside and moves
// on along the line its crack plane (growth direction x front tangent) shares with the surface's
// tangent plane, so the ends of a through crack run along the faces of a thin body.
#include <Eigen/Core>

namespace btfracture {

struct SurfaceSlide {
    bool slides = false;
    Eigen::Vector3d line = Eigen::Vector3d::Zero();  // unit, the side the growth points to
    double along = 0.0;  // |growth . line|: the part of the remaining step that slides
};

// Only a crack plane at least 45 degrees from the surface's tangent plane slides (a shallow one
// would cut a thin flake off along the surface), and only with its growth direction within 50
// degrees of the shared line: the end of a front crossing the surface, not a front arriving
// along it (such as the nodes of a crack's mouth, which point out of the body). The 50 degrees
// are chosen, not derived: with 45 the 2 cm window pane scene no longer separates; from 55 on the
// mouth nodes of the growing slab cracks (tests/crack) slide and EST leaves FULL by up to 32 %.
// `growth` is the unit growth direction, `frontTangent` the front's (any length, 0 = unknown),
// `surfaceNormal` the surface's unit normal there.
SurfaceSlide surfaceSlide(const Eigen::Vector3d& growth, const Eigen::Vector3d& frontTangent,
                          const Eigen::Vector3d& surfaceNormal);

}  // namespace btfracture
