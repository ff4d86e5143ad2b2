// SPDX-License-Identifier: Zlib
#pragma once
// What the voxel-resolution crack fronts (fracture/CrackFront.h) ask of a level-set body: inside
// its uncut solid, which cut crack is at a point, the solid's surface normal. The body must
// outlive the queries.
#include <btFracture/fracture/CrackFront.h>
#include <btFracture/geometry/LevelSetBody.h>

namespace btfracture {

inline FrontQueries levelSetFrontQueries(const LevelSetBody& body) {
    return {[&body](const Eigen::Vector3d& p) { return body.isInsideSolid(p); },
            [&body](const Eigen::Vector3d& p) { return body.crackAt(p); },
            [&body](const Eigen::Vector3d& p) { return body.solidNormal(p); }};
}

}  // namespace btfracture
