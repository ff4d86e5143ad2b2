// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/SurfaceSlide.h>

#include <btFracture/core/PortableMath.h>

#include <Eigen/Geometry>

#include <cmath>

namespace btfracture {
namespace {

const double kSlideMaxCosine = std::sqrt(0.5);
const double kSlideMinCosine = pmath::cos(50.0 * M_PI / 180.0);

}  // namespace

SurfaceSlide surfaceSlide(const Eigen::Vector3d& growth, const Eigen::Vector3d& frontTangent,
                          const Eigen::Vector3d& surfaceNormal) {
    SurfaceSlide s;
    const Eigen::Vector3d crackNormal = growth.cross(frontTangent);
    const bool steep =
        crackNormal.norm() > 0.0 && std::abs(crackNormal.normalized().dot(surfaceNormal)) <= kSlideMaxCosine;
    if (!steep) return s;
    const Eigen::Vector3d shared = crackNormal.cross(surfaceNormal);
    if (shared.norm() <= 0.0) return s;  // no normal known there
    const Eigen::Vector3d line = shared.normalized();
    const double along = line.dot(growth);
    s.line = (along >= 0.0 ? 1.0 : -1.0) * line;
    s.along = std::abs(along);
    s.slides = s.along >= kSlideMinCosine;
    return s;
}

}  // namespace btfracture
