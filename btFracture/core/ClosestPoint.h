#pragma once
// Closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5).
#include <Eigen/Core>

namespace btfracture {

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c);

}  // namespace btfracture
