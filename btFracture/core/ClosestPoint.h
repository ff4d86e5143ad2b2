// SPDX-License-Identifier: Zlib
#pragma once
// Closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5), optionally with
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

inline Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return closestPointAndFeature(p, a, b, c).point;
}

}  // namespace btfracture
