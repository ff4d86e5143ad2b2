// SPDX-License-Identifier: Zlib
#pragma once
// Closest point on a segment, and on a triangle (Ericson, Real-Time Collision Detection, 5.1.2 and
// 5.1.5), the latter optionally with
// the feature (face, edge or vertex) it lies on; the feature selects the pseudonormal for an
// exact inside/outside test against a closed mesh (Baerentzen & Aanaes 2005).
#include <Eigen/Core>

namespace btfracture {

enum class TriangleFeature { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

struct TriangleClosestPoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    TriangleFeature feature = TriangleFeature::Face;
};

// A degenerate (zero-area) triangle yields a point on one of its edges or vertices.
TriangleClosestPoint closestPointAndFeature(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Closest point on the segment a-b (a for a zero-length segment).
inline Eigen::Vector3d closestPointOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    if (!(length2 > 0.0)) return a;
    const double t = (p - a).dot(ab) / length2;
    return a + (t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t) * ab;
}

inline Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return closestPointAndFeature(p, a, b, c).point;
}

}  // namespace btfracture
