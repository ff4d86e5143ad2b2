// SPDX-License-Identifier: Zlib
#include "SurfaceDistance.h"

#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/SurfaceDistance.h>

#include <cmath>

namespace accuracy {

namespace {

// Summed distance from the vertices and centroids of `from` to the surface `to`; adds the count.
void oneWayMean(const btfracture::TriangleMesh& from, const btfracture::ClosestPointTree& to, double& sum,
                int& count) {
    auto visit = [&](const Eigen::Vector3d& p) {
        sum += std::sqrt(to.closestPoint(p).squaredDistance);
        ++count;
    };
    for (const auto& v : from.vertices) visit(v);
    for (const auto& t : from.triangles)
        visit((from.vertices[t[0]] + from.vertices[t[1]] + from.vertices[t[2]]) / 3.0);
}

}  // namespace

SurfaceDistance surfaceDistance(const btfracture::TriangleMesh& a, const btfracture::TriangleMesh& b) {
    SurfaceDistance d;
    if (a.triangles.empty() || b.triangles.empty()) return d;
    const btfracture::ClosestPointTree treeA(a), treeB(b);
    double sum = 0.0;
    int count = 0;
    oneWayMean(a, treeB, sum, count);
    oneWayMean(b, treeA, sum, count);
    d.mean = sum / count;
    d.hausdorff = btfracture::hausdorffDistance(a, b, 0.003);
    return d;
}

}  // namespace accuracy
