// SPDX-License-Identifier: Zlib
#include <btFracture/bem/SurfaceMesh.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>

namespace btfracture {

SurfaceMesh::SurfaceMesh(TriangleMesh mesh) {
    const MeshDefects defects = requireClosedSolid(mesh);
    // Each closed surface adds six rigid motions to the null space of the hypersingular
    // operator (its double layer vanishes outside it), the regulariser of Eq. 1-2 removes six.
    if (defects.components > 1)
        throw Error((mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name) + ": bounded by " +
                    std::to_string(defects.components) +
                    " separate closed surfaces (a cavity, or several solids in one mesh); the BEM "
                    "solver supports solids bounded by one closed surface: give separate solids as "
                    "separate bodies, cavities are not supported");
    const MassProperties mass = computeMassProperties(mesh);
    offset_ = mass.centreOfMass;
    volume_ = mass.volume;

    // Keep only referenced vertices so that every node carries unknowns.
    std::vector<int> newIndex(mesh.vertices.size(), -1);
    for (const auto& tri : mesh.triangles)
        for (int v : tri)
            if (newIndex[v] < 0) {
                newIndex[v] = static_cast<int>(nodes_.size());
                nodes_.push_back(mesh.vertices[v] - offset_);
            }
    triangles_.reserve(mesh.triangles.size());
    for (const auto& tri : mesh.triangles)
        triangles_.push_back({newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]});

    const int m = triangleCount();
    areas_.resize(m);
    diameters_.resize(m);
    normals_.resize(m);
    centroids_.resize(m);
    hatGradients_.resize(m);
    for (int t = 0; t < m; ++t) {
        const Eigen::Vector3d& a = nodes_[triangles_[t][0]];
        const Eigen::Vector3d& b = nodes_[triangles_[t][1]];
        const Eigen::Vector3d& c = nodes_[triangles_[t][2]];
        const Eigen::Vector3d cross = (b - a).cross(c - a);
        const double twiceArea = cross.norm();
        areas_[t] = 0.5 * twiceArea;
        normals_[t] = cross / twiceArea;
        centroids_[t] = (a + b + c) / 3.0;
        diameters_[t] = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        meanDiameter_ += diameters_[t] / m;
        // grad(phi_k) = n x (opposite edge, counter-clockwise) / (2 A)
        const Eigen::Vector3d* corner[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d edge = *corner[(k + 2) % 3] - *corner[(k + 1) % 3];
            hatGradients_[t][k] = normals_[t].cross(edge) / twiceArea;
        }
        surfaceArea_ += areas_[t];
    }
    for (const auto& p : nodes_) radius_ = std::max(radius_, p.norm());

    nodeTriangles_.assign(nodes_.size(), {});
    for (int t = 0; t < m; ++t)
        for (int v : triangles_[t]) nodeTriangles_[v].push_back(t);
    std::map<std::pair<int, int>, int> firstByEdge;
    edgeNeighbours_.assign(m, {-1, -1, -1});
    for (int t = 0; t < m; ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
            auto [it, inserted] = firstByEdge.emplace(std::make_pair(std::min(a, b), std::max(a, b)), t);
            if (!inserted) {
                const int other = it->second;
                edgeNeighbours_[t][k] = other;
                for (int j = 0; j < 3; ++j) {
                    const int c = triangles_[other][j], d = triangles_[other][(j + 1) % 3];
                    if (std::min(c, d) == std::min(a, b) && std::max(c, d) == std::max(a, b))
                        edgeNeighbours_[other][j] = t;
                }
            }
        }
}

bool SurfaceMesh::encloses(const Eigen::Vector3d& p) const {
    return windingNumber(nodes_, triangles_, p) > 0.5;
}

SurfaceMesh::Nearest SurfaceMesh::nearest(const Eigen::Vector3d& p) const {
    Nearest best{-1, std::numeric_limits<double>::infinity(), p};
    for (int t = 0; t < triangleCount(); ++t) {
        const auto& tri = triangles_[t];
        const Eigen::Vector3d c = closestPointOnTriangle(p, nodes_[tri[0]], nodes_[tri[1]], nodes_[tri[2]]);
        const double d = (c - p).norm();
        if (d < best.distance) best = {t, d, c};
    }
    return best;
}

}  // namespace btfracture
