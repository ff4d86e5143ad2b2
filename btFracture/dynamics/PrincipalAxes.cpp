#include <btFracture/dynamics/PrincipalAxes.h>

#include <btFracture/core/Error.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <sstream>

namespace btfracture {

PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia) {
    const Eigen::Matrix3d symmetric = 0.5 * (inertia + inertia.transpose());
    if (!symmetric.allFinite()) {
        std::ostringstream out;
        out << "principalAxes: inertia tensor [" << inertia.format(Eigen::IOFormat(6, 0, ", ", "; ")) << "] is not finite";
        throw Error(out.str());
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(symmetric);
    PrincipalAxes axes;
    axes.moments = eigen.eigenvalues();  // ascending
    axes.rotation = eigen.eigenvectors();
    for (int k = 0; k < 2; ++k) {
        Eigen::Index largest = 0;
        axes.rotation.col(k).cwiseAbs().maxCoeff(&largest);
        if (axes.rotation(largest, k) < 0.0) axes.rotation.col(k) *= -1.0;
    }
    axes.rotation.col(2) = axes.rotation.col(0).cross(axes.rotation.col(1));
    return axes;
}

}  // namespace btfracture
