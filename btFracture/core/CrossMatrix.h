// SPDX-License-Identifier: Zlib
#pragma once
#include <Eigen/Core>

namespace btfracture {

// [c]_x with [c]_x v = c x v.
inline Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& c) {
    Eigen::Matrix3d m;
    m << 0, -c.z(), c.y(), c.z(), 0, -c.x(), -c.y(), c.x(), 0;
    return m;
}

}  // namespace btfracture
