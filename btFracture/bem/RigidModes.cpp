// SPDX-License-Identifier: Zlib
#include <btFracture/bem/RigidModes.h>

#include <btFracture/core/CrossMatrix.h>

#include <Eigen/Geometry>

namespace btfracture {
Eigen::MatrixXd rigidModeOperator(const SurfaceMesh& mesh) {
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(6, 3 * mesh.nodeCount());
    for (int t = 0; t < mesh.triangleCount(); ++t) {
        const auto& tri = mesh.triangle(t);
        const Eigen::Vector3d sum = mesh.node(tri[0]) + mesh.node(tri[1]) + mesh.node(tri[2]);
        const double w = mesh.area(t) / 3.0;
        for (int k = 0; k < 3; ++k) {
            const int p = tri[k];
            T.block<3, 3>(0, 3 * p).diagonal().array() += w;
            // int phi_p x dx = A/3 (x_p + x_a + x_b + x_c) / 4; u x x = -[x]_x u
            const Eigen::Vector3d moment = (mesh.node(p) + sum) / 4.0;
            T.block<3, 3>(3, 3 * p) -= w * crossMatrix(moment);
        }
    }
    return T;
}

Eigen::MatrixXd netLoadOperator(const SurfaceMesh& mesh) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 3 * mesh.triangleCount());
    for (int t = 0; t < mesh.triangleCount(); ++t) {
        A.block<3, 3>(0, 3 * t).diagonal().array() = mesh.area(t);
        A.block<3, 3>(3, 3 * t) = mesh.area(t) * crossMatrix(mesh.centroid(t));
    }
    return A;
}

Eigen::MatrixXd rigidMotions(const SurfaceMesh& mesh) {
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * mesh.nodeCount(), 6);
    for (int p = 0; p < mesh.nodeCount(); ++p) {
        R.block<3, 3>(3 * p, 0).setIdentity();
        R.block<3, 3>(3 * p, 3) = -crossMatrix(mesh.node(p));  // w x x = -[x]_x w
    }
    return R;
}

}  // namespace btfracture
