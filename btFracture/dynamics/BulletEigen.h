// SPDX-License-Identifier: Zlib
#pragma once
// Conversions at the Bullet boundary: btScalar (float or double, per Bullet's build) outside,
// double precision Eigen inside.
#include <LinearMath/btTransform.h>

#include <Eigen/Core>

namespace btfracture {

inline Eigen::Vector3d toEigen(const btVector3& v) {
    return Eigen::Vector3d(double(v.x()), double(v.y()), double(v.z()));
}

inline Eigen::Matrix3d toEigen(const btMatrix3x3& m) {
    Eigen::Matrix3d out;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out(r, c) = double(m[r][c]);
    return out;
}

inline btVector3 toBullet(const Eigen::Vector3d& v) {
    return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}

inline btMatrix3x3 toBullet(const Eigen::Matrix3d& m) {
    return btMatrix3x3(btScalar(m(0, 0)), btScalar(m(0, 1)), btScalar(m(0, 2)), btScalar(m(1, 0)),
                       btScalar(m(1, 1)), btScalar(m(1, 2)), btScalar(m(2, 0)), btScalar(m(2, 1)),
                       btScalar(m(2, 2)));
}

inline btTransform toBullet(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& origin) {
    return btTransform(toBullet(rotation), toBullet(origin));
}

}  // namespace btfracture
