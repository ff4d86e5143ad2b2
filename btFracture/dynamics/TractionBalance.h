// SPDX-License-Identifier: Zlib
#pragma once
// Contact impulses to a piecewise-constant (P0) surface traction field on the BEM mesh, and
// its projection onto zero net force and torque (paper §5.1, Eq. 6).
//
// Each contact adds J n / (t_c A_e) to the triangle e nearest to its point (closest point on the
// surface, not nearest centroid). The balanced field q = q_i - q_c takes the smallest correction
// q_c (Euclidean norm over all 3 x triangles components) with
//   A_f q = sum_e A_e q_e = 0                 (net force)
//   A_tau q = sum_e A_e c_e x q_e = 0         (net torque about the origin; c_e = centroid),
// i.e. q_c = A^T (A A^T)^-1 A q_i with the 6x6 matrix A A^T built in one pass over the triangles.
// Units: positions [m], areas [m^2], tractions [Pa], impulses [N s], durations [s].
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/dynamics/BodyContact.h>
#include <btFracture/dynamics/ClosestSurfacePoint.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

using TractionField = std::vector<Eigen::Vector3d>;  // one traction [Pa] per triangle

struct NetLoad {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   // sum A_e q_e [N]
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // sum A_e c_e x q_e [N m]
    double forceScale = 0.0;                           // sum A_e |q_e| [N], for relative checks
    double torqueScale = 0.0;                          // sum A_e |c_e| |q_e| [N m]
};

// Precomputes areas, centroids and the factored 6x6 matrix A A^T of one BEM mesh (the mesh is
// expected in the body frame, centred at the centre of mass; torque is taken about its origin).
class TractionBalancer {
public:
    // Throws btfracture::Error naming mesh.name when the mesh is empty, has an invalid index or a
    // non-finite vertex, or when A A^T is singular (zero total area, or all centroids on one line
    // through the origin so that torque about that line cannot be controlled).
    explicit TractionBalancer(TriangleMesh bemMesh);

    const TriangleMesh& mesh() const { return mesh_; }
    const std::vector<double>& areas() const { return areas_; }
    const std::vector<Eigen::Vector3d>& centroids() const { return centroids_; }

    ClosestSurfacePoint closestSurfacePoint(const Eigen::Vector3d& point) const;

    // Input field q_i: each contact's J n / (t_c A_e) on its nearest triangle. Throws on a contact
    // with non-finite data, negative impulse, non-positive duration or zero direction.
    TractionField contactTractions(const std::vector<BodyContact>& contacts) const;

    NetLoad netLoad(const TractionField& q) const;

    // q - q_c, the force- and torque-free field nearest to q (Eq. 6). Throws when q has the
    // wrong size or a non-finite entry.
    TractionField balance(const TractionField& q) const;

private:
    TriangleMesh mesh_;
    std::vector<double> areas_;
    std::vector<Eigen::Vector3d> centroids_;
    double torqueRowScale_ = 1.0;                // 1/L: torque rows scaled to force units for conditioning
    Eigen::Matrix<double, 6, 6> inverseNormal_;  // (A' A'^T)^-1 with the scaled rows A'
};

}  // namespace btfracture
