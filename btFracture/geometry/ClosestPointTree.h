// SPDX-License-Identifier: Zlib
#pragma once
// Bounding-volume hierarchy over the triangles of a mesh that answers "closest point on the
// surface" queries; used to project remeshed vertices back onto an input surface and to
// measure the distance between two surfaces.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace btfracture {

class ClosestPointTree {
public:
    struct Hit {
        Eigen::Vector3d point = Eigen::Vector3d::Zero();  // closest surface point [mesh units]
        int triangle = -1;                                // index into the mesh's triangles
        double squaredDistance = 0.0;
    };

    // Keeps a copy of the mesh. Throws btfracture::Error naming mesh.name if it has no triangles
    // or an index out of range.
    explicit ClosestPointTree(const TriangleMesh& mesh);

    Hit closestPoint(const Eigen::Vector3d& query) const;
    // Closest point among the triangles whose unit normal n satisfies n . normal >= minCosine, so
    // that a point on one side of a thin part is not pulled onto the other side. Falls back to
    // closestPoint(query) when no triangle qualifies.
    Hit closestPoint(const Eigen::Vector3d& query, const Eigen::Vector3d& normal, double minCosine) const;
    // The same without the fallback, among the points closer than maxDistance: triangle -1 when
    // no qualifying triangle comes that close.
    Hit closestPointWithin(const Eigen::Vector3d& query, const Eigen::Vector3d& normal, double minCosine,
                           double maxDistance) const;

    const TriangleMesh& mesh() const { return mesh_; }
    // Unit outward normal of a triangle (zero for a degenerate one).
    const Eigen::Vector3d& triangleNormal(int t) const { return normals_[t]; }

private:
    struct Node {
        Eigen::AlignedBox3d box;
        int first = 0;  // leaf: first entry in order_; inner: index of the left child
        int count = 0;  // leaf: number of triangles; inner: 0
        int right = 0;  // inner: index of the right child
    };
    int build(int first, int count);
    template <class Accept>
    Hit search(const Eigen::Vector3d& query, Accept&& accept, double maxSquaredDistance) const;

    TriangleMesh mesh_;
    std::vector<Eigen::Vector3d> normals_;
    std::vector<int> order_;  // triangle indices, grouped by leaf
    std::vector<Node> nodes_;
};

}  // namespace btfracture
