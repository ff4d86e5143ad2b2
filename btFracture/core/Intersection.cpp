// SPDX-License-Identifier: Zlib
#include <btFracture/core/Intersection.h>

#include <btFracture/core/PortableMath.h>

#include <Eigen/Geometry>

#include <cmath>

namespace btfracture {

double windingNumber(const std::vector<Eigen::Vector3d>& vertices,
                     const std::vector<std::array<int, 3>>& triangles, const Eigen::Vector3d& p) {
    double sum = 0.0;
    for (const auto& t : triangles) {
        const Eigen::Vector3d a = vertices[t[0]] - p, b = vertices[t[1]] - p, c = vertices[t[2]] - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double det = a.dot(b.cross(c));
        const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        sum += 2.0 * pmath::atan2(det, den);
    }
    return sum / (4.0 * M_PI);
}

double segmentTriangleHit(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d dir = q - p, e1 = b - a, e2 = c - a;
    const Eigen::Vector3d h = dir.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300) return -1.0;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = p - a;
    const double u = inv * s.dot(h);
    if (u < 0.0 || u > 1.0) return -1.0;
    const Eigen::Vector3d k = s.cross(e1);
    const double v = inv * dir.dot(k);
    if (v < 0.0 || u + v > 1.0) return -1.0;
    const double t = inv * e2.dot(k);
    return (t >= 0.0 && t <= 1.0) ? t : -1.0;
}

}  // namespace btfracture
