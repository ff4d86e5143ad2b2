// SPDX-License-Identifier: Zlib
#include <btFracture/bem/SurfaceStress.h>

#include <Eigen/Geometry>

namespace btfracture {

Eigen::Matrix3d surfaceStress(const SurfaceMesh& mesh, double E, double nu, int t, const Eigen::VectorXd& u,
                              const Eigen::Vector3d& q) {
    const auto& tri = mesh.triangle(t);
    const Eigen::Vector3d n1 = mesh.normal(t);
    const Eigen::Vector3d n2 = (mesh.node(tri[1]) - mesh.node(tri[0])).normalized();
    const Eigen::Vector3d n3 = n1.cross(n2);

    // In-plane strain of the P1 displacement in the (n2, n3) frame.
    double e22 = 0.0, e33 = 0.0, g23 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d uk = u.segment<3>(3 * tri[k]);
        const Eigen::Vector3d& grad = mesh.hatGradient(t, k);
        const double u2 = uk.dot(n2), u3 = uk.dot(n3), d2 = grad.dot(n2), d3 = grad.dot(n3);
        e22 += u2 * d2;
        e33 += u3 * d3;
        g23 += u2 * d3 + u3 * d2;
    }
    // Plane-stress Hooke's law, E* = E / (1 - nu^2).
    const double Es = E / (1.0 - nu * nu);
    const double s22 = Es * (e22 + nu * e33), s33 = Es * (e33 + nu * e22), s23 = Es * 0.5 * (1.0 - nu) * g23;

    // Rotated 2D stress columns, then the traction-consistent and Poisson corrections (§4.1).
    const double poisson = nu / (1.0 - nu);
    const Eigen::Vector3d q2 = n2 * s22 + n3 * s23 + n1 * q.dot(n2) + n2 * (q.dot(n1) * poisson);
    const Eigen::Vector3d q3 = n2 * s23 + n3 * s33 + n1 * q.dot(n3) + n3 * (q.dot(n1) * poisson);
    // Eq. 5: sigma = (q q2 q3)(n1 n2 n3)^T
    return q * n1.transpose() + q2 * n2.transpose() + q3 * n3.transpose();
}

std::vector<Eigen::Matrix3d> surfaceStresses(const SurfaceMesh& mesh, double E, double nu,
                                             const Eigen::VectorXd& u, const Eigen::VectorXd& q) {
    std::vector<Eigen::Matrix3d> out(mesh.triangleCount());
    for (int t = 0; t < mesh.triangleCount(); ++t)
        out[t] = surfaceStress(mesh, E, nu, t, u, q.segment<3>(3 * t));
    return out;
}

}  // namespace btfracture
