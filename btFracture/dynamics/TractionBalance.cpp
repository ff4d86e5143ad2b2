// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/TractionBalance.h>

#include <btFracture/core/Error.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

std::string meshName(const TriangleMesh& mesh) {
    return mesh.name.empty() ? std::string("<unnamed BEM mesh>") : mesh.name;
}

// Below this ratio of smallest to largest eigenvalue of the scaled A A^T the constraints are
// treated as dependent.
constexpr double kSingularRatio = 1e-12;

}  // namespace

TractionBalancer::TractionBalancer(TriangleMesh bemMesh) : mesh_(std::move(bemMesh)) {
    const std::string name = meshName(mesh_);
    const int nv = static_cast<int>(mesh_.vertices.size());
    if (mesh_.triangles.empty()) throw Error(name + ": traction balancing needs a BEM mesh with triangles");
    for (const auto& v : mesh_.vertices)
        if (!v.allFinite()) throw Error(name + ": BEM mesh has a non-finite vertex");

    const std::size_t nt = mesh_.triangles.size();
    areas_.resize(nt);
    centroids_.resize(nt);
    double sumArea2 = 0.0, sumArea2Radius2 = 0.0;
    for (std::size_t e = 0; e < nt; ++e) {
        const auto& tri = mesh_.triangles[e];
        for (int i : tri)
            if (i < 0 || i >= nv) {
                std::ostringstream out;
                out << name << ": BEM triangle " << e << " has corner index " << i << " outside [0, " << nv
                    << ")";
                throw Error(out.str());
            }
        const Eigen::Vector3d& a = mesh_.vertices[tri[0]];
        const Eigen::Vector3d& b = mesh_.vertices[tri[1]];
        const Eigen::Vector3d& c = mesh_.vertices[tri[2]];
        areas_[e] = 0.5 * (b - a).cross(c - a).norm();
        centroids_[e] = (a + b + c) / 3.0;
        sumArea2 += areas_[e] * areas_[e];
        sumArea2Radius2 += areas_[e] * areas_[e] * centroids_[e].squaredNorm();
    }
    if (!(sumArea2 > 0.0))
        throw Error(name +
                    ": traction balancing: A A^T is singular because the BEM mesh has zero total area");

    // Scale the torque rows by 1/L (L = area-weighted RMS centroid radius) so that both row
    // blocks have the same units; the constraint set and the minimum-norm correction are unchanged.
    const double length = std::sqrt(sumArea2Radius2 / sumArea2);
    torqueRowScale_ = length > 0.0 ? 1.0 / length : 1.0;

    // A' A'^T = sum_e A_e^2 [[I, s [c]x^T], [s [c]x, s^2 [c]x [c]x^T]], s = torqueRowScale_.
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    for (std::size_t e = 0; e < nt; ++e) {
        const Eigen::Vector3d c = centroids_[e] * torqueRowScale_;
        Eigen::Matrix3d cross;
        cross << 0.0, -c.z(), c.y(), c.z(), 0.0, -c.x(), -c.y(), c.x(), 0.0;
        const double w = areas_[e] * areas_[e] / sumArea2;
        normal.topLeftCorner<3, 3>() += w * Eigen::Matrix3d::Identity();
        normal.topRightCorner<3, 3>() += w * cross.transpose();
        normal.bottomLeftCorner<3, 3>() += w * cross;
        normal.bottomRightCorner<3, 3>() += w * cross * cross.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(normal);
    const auto& lambda = eigen.eigenvalues();  // ascending
    if (eigen.info() != Eigen::Success || !(lambda(0) > kSingularRatio * lambda(5))) {
        const Eigen::Matrix<double, 6, 1> weakest = eigen.eigenvectors().col(0);
        std::ostringstream out;
        out << name << ": traction balancing: A A^T is singular (smallest/largest eigenvalue "
            << lambda(0) / lambda(5) << " < " << kSingularRatio
            << "); its weakest combination has force part [" << weakest.head<3>().transpose()
            << "] and torque part [" << weakest.tail<3>().transpose()
            << "]: the triangle centroids lie on one line through the origin, so the torque about that line "
               "cannot be controlled by P0 tractions";
        throw Error(out.str());
    }
    inverseNormal_ =
        eigen.eigenvectors() * lambda.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
    // Undo the 1/sumArea2 normalisation of the matrix: (A'A'^T)^-1 = inverseNormal_ / sumArea2.
    inverseNormal_ /= sumArea2;
}

ClosestSurfacePoint TractionBalancer::closestSurfacePoint(const Eigen::Vector3d& point) const {
    return btfracture::closestSurfacePoint(mesh_, point);
}

TractionField TractionBalancer::contactTractions(const std::vector<BodyContact>& contacts) const {
    TractionField q(mesh_.triangles.size(), Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const BodyContact& c = contacts[k];
        std::ostringstream problem;
        if (!c.point.allFinite())
            problem << "non-finite point";
        else if (!(c.impulse >= 0.0) || !std::isfinite(c.impulse))
            problem << "impulse " << c.impulse << " N s (need >= 0)";
        else if (!(c.duration > 0.0) || !std::isfinite(c.duration))
            problem << "contact duration " << c.duration << " s (need > 0)";
        else if (!c.direction.allFinite() || !(c.direction.norm() > 0.0))
            problem << "zero or non-finite direction";
        if (problem.tellp() > 0) {
            std::ostringstream out;
            out << meshName(mesh_) << ": contact " << k << ": " << problem.str();
            throw Error(out.str());
        }
        const int e = closestSurfacePoint(c.point).triangle;
        q[e] += c.impulse / (c.duration * areas_[e]) * c.direction.normalized();
    }
    return q;
}

NetLoad TractionBalancer::netLoad(const TractionField& q) const {
    NetLoad load;
    const std::size_t n = std::min(q.size(), areas_.size());
    for (std::size_t e = 0; e < n; ++e) {
        load.force += areas_[e] * q[e];
        load.torque += areas_[e] * centroids_[e].cross(q[e]);
        load.forceScale += areas_[e] * q[e].norm();
        load.torqueScale += areas_[e] * centroids_[e].norm() * q[e].norm();
    }
    return load;
}

TractionField TractionBalancer::balance(const TractionField& q) const {
    if (q.size() != areas_.size()) {
        std::ostringstream out;
        out << meshName(mesh_) << ": traction field has " << q.size() << " entries for " << areas_.size()
            << " BEM triangles";
        throw Error(out.str());
    }
    // b' = A' q with the torque rows scaled.
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t e = 0; e < q.size(); ++e) {
        if (!q[e].allFinite()) {
            std::ostringstream out;
            out << meshName(mesh_) << ": traction on BEM triangle " << e << " is not finite";
            throw Error(out.str());
        }
        b.head<3>() += areas_[e] * q[e];
        b.tail<3>() += areas_[e] * torqueRowScale_ * centroids_[e].cross(q[e]);
    }
    const Eigen::Matrix<double, 6, 1> v = inverseNormal_ * b;
    const Eigen::Vector3d vf = v.head<3>();
    const Eigen::Vector3d vt = torqueRowScale_ * v.tail<3>();
    // Block e of A'^T v: A_e (v_f + s [c_e]x^T v_t) = A_e (v_f + s v_t x c_e).
    TractionField balanced(q.size());
    for (std::size_t e = 0; e < q.size(); ++e)
        balanced[e] = q[e] - areas_[e] * (vf + vt.cross(centroids_[e]));
    return balanced;
}

}  // namespace btfracture
