// SPDX-License-Identifier: Zlib
#pragma once
// The BEM's boundary mesh: flat triangles with P1 nodes, centred at the solid's centre of mass
// (paper §3, "without loss of generality"), with the per-triangle data every operator needs.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace btfracture {

class SurfaceMesh {
public:
    // Validates `mesh` (closed, manifold, consistently oriented; inside-out is flipped with a
    // warning; one closed surface, no cavities or separate shells) and translates it so that the enclosed
    // solid's centre of mass is the origin.
    explicit SurfaceMesh(TriangleMesh mesh);

    int nodeCount() const { return static_cast<int>(nodes_.size()); }
    int triangleCount() const { return static_cast<int>(triangles_.size()); }
    const std::vector<Eigen::Vector3d>& nodes() const { return nodes_; }
    const Eigen::Vector3d& node(int i) const { return nodes_[i]; }
    const std::array<int, 3>& triangle(int t) const { return triangles_[t]; }
    const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

    double area(int t) const { return areas_[t]; }
    const Eigen::Vector3d& normal(int t) const { return normals_[t]; }  // outward unit normal
    const Eigen::Vector3d& centroid(int t) const { return centroids_[t]; }
    double diameter(int t) const { return diameters_[t]; }  // longest edge
    double meanDiameter() const { return meanDiameter_; }   // over the triangles [m]
    // Surface gradient of the P1 hat function of local corner k on triangle t (constant there).
    const Eigen::Vector3d& hatGradient(int t, int k) const { return hatGradients_[t][k]; }
    // Surface curl n x grad(phi) of that hat function (appendix Eq. 8 after integration by parts).
    Eigen::Vector3d hatCurl(int t, int k) const { return normals_[t].cross(hatGradients_[t][k]); }

    // Triangles around each node and the (up to three) edge neighbours of each triangle.
    const std::vector<int>& trianglesAtNode(int i) const { return nodeTriangles_[i]; }
    const std::array<int, 3>& edgeNeighbours(int t) const { return edgeNeighbours_[t]; }

    // The translation that was applied: original coordinates = nodes() + offset().
    const Eigen::Vector3d& offset() const { return offset_; }
    double surfaceArea() const { return surfaceArea_; }
    double volume() const { return volume_; }
    // Radius of the smallest origin-centred ball holding the mesh; the natural length scale.
    double radius() const { return radius_; }

    // Whether p lies inside the solid (generalised winding number above 1/2).
    bool encloses(const Eigen::Vector3d& p) const;
    // The surface point nearest to p, brute force over the triangles (the lowest index among
    // equally near ones).
    struct Nearest {
        int triangle;
        double distance;  // [m]
        Eigen::Vector3d point;
    };
    Nearest nearest(const Eigen::Vector3d& p) const;

private:
    std::vector<Eigen::Vector3d> nodes_;
    std::vector<std::array<int, 3>> triangles_;
    std::vector<double> areas_, diameters_;
    double meanDiameter_ = 0.0;
    std::vector<Eigen::Vector3d> normals_, centroids_;
    std::vector<std::array<Eigen::Vector3d, 3>> hatGradients_;
    std::vector<std::vector<int>> nodeTriangles_;
    std::vector<std::array<int, 3>> edgeNeighbours_;
    Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
    double surfaceArea_ = 0.0, volume_ = 0.0, radius_ = 0.0;
};

}  // namespace btfracture
