// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/MeshInset.h>

#include <btFracture/core/Error.h>
#include <btFracture/geometry/ClosestPointTree.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace btfracture {

namespace {

constexpr double kFlatDirection = 1e-3;  // eigenvalues below this times the largest: no move (~2 degrees)
constexpr double kLongestMove = 3.0;
constexpr double kClearance = 0.8;
constexpr int kHalvings = 4;

}  // namespace

MeshInset insetMesh(const TriangleMesh& mesh, double distance) {
    const std::string name = mesh.name.empty() ? std::string("mesh") : mesh.name;
    if (!(distance >= 0.0) || !std::isfinite(distance)) {
        std::ostringstream out;
        out << name << ": inset distance " << distance << " m (need finite, >= 0)";
        throw Error(out.str());
    }
    MeshInset out;
    out.mesh = mesh;
    if (distance == 0.0 || mesh.triangles.empty()) return out;
    const ClosestPointTree surface(mesh);  // throws on a triangle index out of range

    // Per vertex: the normal equations of sum_f A_f (n_f . delta + d)^2 (trace: the vertex's area).
    const int n = static_cast<int>(mesh.vertices.size());
    std::vector<Eigen::Matrix3d> normal(n, Eigen::Matrix3d::Zero());
    std::vector<Eigen::Vector3d> rhs(n, Eigen::Vector3d::Zero());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d cross =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        const double twiceArea = cross.norm();
        if (twiceArea <= 0.0) continue;
        const Eigen::Vector3d nf = cross / twiceArea;
        const double a = 0.5 * twiceArea;
        for (int c : t) {
            normal[c] += a * nf * nf.transpose();
            rhs[c] -= a * distance * nf;
        }
    }
    for (int v = 0; v < n; ++v) {
        if (normal[v].trace() <= 0.0) continue;
        // Least-squares move, the smallest one where the planes leave a direction free (pseudo-inverse).
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(normal[v]);
        const double largest = eigen.eigenvalues()(2);
        Eigen::Vector3d delta = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
            const double lambda = eigen.eigenvalues()(k);
            if (lambda <= kFlatDirection * largest) continue;
            const Eigen::Vector3d axis = eigen.eigenvectors().col(k);
            delta += axis * (axis.dot(rhs[v]) / lambda);
        }
        const double length = delta.norm();
        if (!std::isfinite(length)) continue;
        if (length > kLongestMove * distance) delta *= kLongestMove * distance / length;
        const Eigen::Vector3d& p = mesh.vertices[v];
        // Largest of 1, 1/2, ..., 1/16 (else 0) of `move` that leaves the moved vertex inside,
        // at least kClearance of the move's depth from every part of the surface.
        const auto reach = [&](const Eigen::Vector3d& move, double depth) {
            double scale = 1.0;
            for (int halvings = 0; halvings <= kHalvings; ++halvings, scale *= 0.5) {
                const Eigen::Vector3d q = p + scale * move;
                const ClosestPointTree::Hit hit = surface.closestPoint(q);
                const bool inside = (q - hit.point).dot(surface.triangleNormal(hit.triangle)) < 0.0;
                if (inside && std::sqrt(hit.squaredDistance) >= kClearance * scale * depth) return scale;
            }
            return 0.0;
        };
        // The depth the move reaches: d where the planes move by d, less where it was capped.
        double depth = std::min(distance, delta.norm());
        double scale = reach(delta, depth);
        // A spike or fin the planes' move cannot enter: along the inward normal instead.
        const Eigen::Vector3d inward = rhs[v].normalized() * distance;
        if (scale < 1.0 && inward.allFinite()) {
            const double alongNormal = reach(inward, distance);
            if (alongNormal * distance > scale * depth) {
                delta = inward;
                depth = distance;
                scale = alongNormal;
            }
        }
        const double fraction = scale * depth / distance;
        out.mesh.vertices[v] = p + scale * delta;
        out.smallestFraction = std::min(out.smallestFraction, fraction);
        if (fraction < 0.99) ++out.reducedVertices;
    }
    return out;
}

}  // namespace btfracture
