// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ClosestPointTree.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace btfracture {

ClosestPointTree::ClosestPointTree(const TriangleMesh& mesh) : mesh_(mesh) {
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (mesh.triangles.empty()) throw Error(source + ": closest-point tree needs at least one triangle");
    const int nv = static_cast<int>(mesh.vertices.size());
    normals_.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (int i : tri)
            if (i < 0 || i >= nv)
                throw Error(source + ": triangle " + std::to_string(t) + " has vertex index " +
                            std::to_string(i) + " outside [0, " + std::to_string(nv) + ")");
        const Eigen::Vector3d n = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                                      .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
        const double length = n.norm();
        normals_.push_back(length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero());
    }
    order_.resize(mesh.triangles.size());
    std::iota(order_.begin(), order_.end(), 0);
    nodes_.reserve(2 * mesh.triangles.size());
    build(0, static_cast<int>(order_.size()));
}

int ClosestPointTree::build(int first, int count) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Eigen::AlignedBox3d box, centres;
    auto centroid = [this](int t) {
        const auto& tri = mesh_.triangles[t];
        return Eigen::Vector3d((mesh_.vertices[tri[0]] + mesh_.vertices[tri[1]] + mesh_.vertices[tri[2]]) /
                               3.0);
    };
    for (int i = first; i < first + count; ++i) {
        const auto& tri = mesh_.triangles[order_[i]];
        for (int v : tri) box.extend(mesh_.vertices[v]);
        centres.extend(centroid(order_[i]));
    }
    nodes_[index].box = box;
    constexpr int leafSize = 4;
    if (count <= leafSize) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    // Median split along the longest axis of the centroids (ties broken by triangle index).
    int axis = 0;
    centres.sizes().maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int s, int t) {
                         const double cs = centroid(s)[axis], ct = centroid(t)[axis];
                         return cs < ct || (cs == ct && s < t);
                     });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[index].first = left;
    nodes_[index].count = 0;
    nodes_[index].right = right;
    return index;
}

template <class Accept>
ClosestPointTree::Hit ClosestPointTree::search(const Eigen::Vector3d& query, Accept&& accept,
                                               double maxSquaredDistance) const {
    Hit best;
    best.squaredDistance = maxSquaredDistance;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.box.squaredExteriorDistance(query) >= best.squaredDistance) continue;
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i) {
                const int t = order_[i];
                if (!accept(t)) continue;
                const auto& tri = mesh_.triangles[t];
                const Eigen::Vector3d p = closestPointOnTriangle(
                    query, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
                const double d2 = (p - query).squaredNorm();
                if (d2 < best.squaredDistance || (d2 == best.squaredDistance && t < best.triangle)) {
                    best.point = p;
                    best.triangle = t;
                    best.squaredDistance = d2;
                }
            }
            continue;
        }
        // Visit the nearer child first: push it last.
        const int left = node.first, right = node.right;
        const double dl = nodes_[left].box.squaredExteriorDistance(query);
        const double dr = nodes_[right].box.squaredExteriorDistance(query);
        if (dl <= dr) {
            stack[top++] = right;
            stack[top++] = left;
        } else {
            stack[top++] = left;
            stack[top++] = right;
        }
    }
    return best;
}

ClosestPointTree::Hit ClosestPointTree::closestPoint(const Eigen::Vector3d& query) const {
    return search(
        query, [](int) { return true; }, std::numeric_limits<double>::infinity());
}

ClosestPointTree::Hit ClosestPointTree::closestPoint(const Eigen::Vector3d& query,
                                                     const Eigen::Vector3d& normal, double minCosine) const {
    const Hit hit = search(
        query, [&](int t) { return normals_[t].dot(normal) >= minCosine; },
        std::numeric_limits<double>::infinity());
    return hit.triangle >= 0 ? hit : closestPoint(query);
}

ClosestPointTree::Hit ClosestPointTree::closestPointWithin(const Eigen::Vector3d& query,
                                                           const Eigen::Vector3d& normal, double minCosine,
                                                           double maxDistance) const {
    return search(
        query, [&](int t) { return normals_[t].dot(normal) >= minCosine; }, maxDistance * maxDistance);
}

}  // namespace btfracture
