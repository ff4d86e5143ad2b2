// SPDX-License-Identifier: Zlib
#include <btFracture/core/MassProperties.h>

#include <btFracture/core/Error.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <sstream>

namespace btfracture {

MassProperties computeMassProperties(const TriangleMesh& mesh) {
    double volume = 0.0;
    Eigen::Vector3d firstMoment = Eigen::Vector3d::Zero();
    Eigen::Matrix3d secondMoment = Eigen::Matrix3d::Zero();  // integral of x x^T over the solid
    for (const auto& tri : mesh.triangles) {
        const Eigen::Vector3d& a = mesh.vertices[tri[0]];
        const Eigen::Vector3d& b = mesh.vertices[tri[1]];
        const Eigen::Vector3d& c = mesh.vertices[tri[2]];
        const double det = a.dot(b.cross(c));  // 6 x signed volume of tetrahedron (0, a, b, c)
        const Eigen::Vector3d s = a + b + c;
        volume += det / 6.0;
        firstMoment += det / 24.0 * s;
        // Tetrahedron with a vertex at the origin: V/20 (a a^T + b b^T + c c^T + s s^T).
        secondMoment +=
            det / 120.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    if (!(volume > 0.0)) {
        std::ostringstream msg;
        msg << (mesh.name.empty() ? "<unnamed mesh>" : mesh.name)
            << ": enclosed volume must be positive for mass properties, got " << volume;
        throw Error(msg.str());
    }
    MassProperties p;
    p.volume = volume;
    p.centreOfMass = firstMoment / volume;
    const Eigen::Matrix3d central = secondMoment - volume * p.centreOfMass * p.centreOfMass.transpose();
    p.inertiaPerDensity = central.trace() * Eigen::Matrix3d::Identity() - central;
    return p;
}

double enclosedVolume(const TriangleMesh& mesh, const Eigen::Vector3d& about) {
    double volume = 0.0;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = mesh.vertices[t[0]] - about, b = mesh.vertices[t[1]] - about,
                              c = mesh.vertices[t[2]] - about;
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

double surfaceArea(const TriangleMesh& mesh) {
    double area = 0.0;
    for (const auto& t : mesh.triangles)
        area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                          .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                          .norm();
    return area;
}

PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia) {
    if (!inertia.allFinite()) {
        std::ostringstream msg;
        msg << "principal axes of a non-finite inertia tensor: "
            << inertia.format(Eigen::IOFormat(6, 0, ", ", "; ", "", "", "[", "]"));
        throw Error(msg.str());
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(0.5 * (inertia + inertia.transpose()));
    PrincipalAxes axes;
    axes.moments = eigen.eigenvalues();
    axes.rotation = eigen.eigenvectors();
    for (int k = 0; k < 2; ++k) {
        Eigen::Index largest;
        axes.rotation.col(k).cwiseAbs().maxCoeff(&largest);
        if (axes.rotation(largest, k) < 0.0) axes.rotation.col(k) = -axes.rotation.col(k);
    }
    axes.rotation.col(2) = axes.rotation.col(0).cross(axes.rotation.col(1));
    return axes;
}

}  // namespace btfracture
