#include <btFracture/geometry/MassProperties.h>

#include <btFracture/core/Error.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>

namespace btfracture {

MassProperties computeMassProperties(const TriangleMesh& mesh) {
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (mesh.vertices.empty() || mesh.triangles.empty())
        throw Error(source + ": cannot compute mass properties of an empty mesh");

    // Integrate relative to the bounding-box centre to limit cancellation far from the origin.
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const Eigen::Vector3d ref = 0.5 * (lo + hi);

    // Tetrahedron (ref, a, b, c): V = a.(b x c)/6, first moment V (a+b+c)/4,
    // second moment integral of x x^T dV = V/20 (sum a a^T + s s^T), s = a+b+c (relative to ref).
    double volume = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    const int nv = static_cast<int>(mesh.vertices.size());
    for (const auto& tri : mesh.triangles) {
        for (int i : tri)
            if (i < 0 || i >= nv) {
                std::ostringstream out;
                out << source << ": triangle corner index " << i << " outside [0, " << nv << ")";
                throw Error(out.str());
            }
        const Eigen::Vector3d a = mesh.vertices[tri[0]] - ref;
        const Eigen::Vector3d b = mesh.vertices[tri[1]] - ref;
        const Eigen::Vector3d c = mesh.vertices[tri[2]] - ref;
        const double v = a.dot(b.cross(c)) / 6.0;
        const Eigen::Vector3d s = a + b + c;
        volume += v;
        first += v * s / 4.0;
        second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    if (!(volume > 0.0) || !std::isfinite(volume)) {
        std::ostringstream out;
        out << source << ": enclosed volume is " << volume
            << " m^3; mass properties need a closed, outward-oriented mesh";
        throw Error(out.str());
    }
    MassProperties mp;
    mp.volume = volume;
    const Eigen::Vector3d centre = first / volume;  // relative to ref
    mp.centreOfMass = ref + centre;
    const Eigen::Matrix3d covariance = second - volume * centre * centre.transpose();
    mp.inertiaAboutCom = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
    return mp;
}

PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia) {
    const Eigen::Matrix3d symmetric = 0.5 * (inertia + inertia.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(symmetric);
    if (eigen.info() != Eigen::Success || !symmetric.allFinite()) {
        std::ostringstream out;
        out << "principalAxes: eigen decomposition failed for inertia tensor [" << inertia.format(
                                                                                   Eigen::IOFormat(6, 0, ", ", "; "))
            << "]";
        throw Error(out.str());
    }
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
