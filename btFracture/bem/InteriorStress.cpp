// SPDX-License-Identifier: Zlib
#include <btFracture/bem/InteriorStress.h>

#include <btFracture/bem/Quadrature.h>
#include <btFracture/bem/SurfaceStress.h>
#include <btFracture/core/ClosestPoint.h>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

// Kelvin stress kernels of Eq. 7 (in the form of Brebbia & Dominguez, which fixes the index
// typo of the paper's S2 n_i / n_j terms), accumulated as w (S1 q - S2 u) into sigma.
void addSomiglianaStress(const Eigen::Vector3d& x, const Eigen::Vector3d& y, const Eigen::Vector3d& n,
                         const Eigen::Vector3d& q, const Eigen::Vector3d& u, double E, double nu, double w,
                         Eigen::Matrix3d& sigma) {
    const Eigen::Vector3d d = y - x;
    const double r = d.norm();
    const Eigen::Vector3d g = d / r;  // dr/dy_i
    const double dn = g.dot(n);
    const double c1 = w / (8.0 * M_PI * (1.0 - nu) * r * r);
    const double c2 = w * E / (8.0 * M_PI * (1.0 - nu * nu) * r * r * r);
    const double gq = g.dot(q), gu = g.dot(u), nu_u = n.dot(u);
    const double a = 1.0 - 2.0 * nu;
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            const double dij = i == j ? 1.0 : 0.0;
            // sum_k S1_ijk q_k
            const double s1 = a * (q[j] * g[i] + q[i] * g[j] - dij * gq) + 3.0 * g[i] * g[j] * gq;
            // sum_k S2_ijk u_k
            const double s2 =
                3.0 * dn * (a * dij * gu + nu * (u[j] * g[i] + u[i] * g[j]) - 5.0 * g[i] * g[j] * gu) +
                3.0 * nu * (n[i] * g[j] + n[j] * g[i]) * gu +
                a * (3.0 * nu_u * g[i] * g[j] + n[j] * u[i] + n[i] * u[j]) - (1.0 - 4.0 * nu) * nu_u * dij;
            sigma(i, j) += c1 * s1 - c2 * s2;
        }
}

struct SubTriangle {
    Eigen::Vector3d corner[3];
    Eigen::Vector3d u[3];  // displacement at the corners (linear in between)
    double area;
};

void integrateAdaptive(const Eigen::Vector3d& x, const SubTriangle& s, const Eigen::Vector3d& n,
                       const Eigen::Vector3d& q, double E, double nu,
                       const StressEvaluationSettings& settings, int depth, Eigen::Matrix3d& sigma) {
    const Eigen::Vector3d closest = closestPointOnTriangle(x, s.corner[0], s.corner[1], s.corner[2]);
    const double size = std::max({(s.corner[1] - s.corner[0]).norm(), (s.corner[2] - s.corner[1]).norm(),
                                  (s.corner[0] - s.corner[2]).norm()});
    const double distance = (closest - x).norm();
    if (distance < settings.subdivisionRatio * size && depth < settings.maxSubdivisions) {
        Eigen::Vector3d m[3], um[3];
        for (int k = 0; k < 3; ++k) {
            m[k] = 0.5 * (s.corner[k] + s.corner[(k + 1) % 3]);
            um[k] = 0.5 * (s.u[k] + s.u[(k + 1) % 3]);
        }
        const double quarter = 0.25 * s.area;
        const SubTriangle children[4] = {{{s.corner[0], m[0], m[2]}, {s.u[0], um[0], um[2]}, quarter},
                                         {{m[0], s.corner[1], m[1]}, {um[0], s.u[1], um[1]}, quarter},
                                         {{m[2], m[1], s.corner[2]}, {um[2], um[1], s.u[2]}, quarter},
                                         {{m[1], m[2], m[0]}, {um[1], um[2], um[0]}, quarter}};
        for (const auto& child : children)
            integrateAdaptive(x, child, n, q, E, nu, settings, depth + 1, sigma);
        return;
    }
    const int degree = distance >= settings.veryFarRatio * size ? settings.veryFarDegree
                       : distance >= settings.farRatio * size   ? settings.farDegree
                                                                : settings.ruleDegree;
    for (const auto& p : triangleRule(degree).points) {
        const Eigen::Vector3d y = p.l0 * s.corner[0] + p.l1 * s.corner[1] + p.l2 * s.corner[2];
        const Eigen::Vector3d uy = p.l0 * s.u[0] + p.l1 * s.u[1] + p.l2 * s.u[2];
        addSomiglianaStress(x, y, n, q, uy, E, nu, p.w * s.area, sigma);
    }
}

}  // namespace

StressEvaluator::StressEvaluator(const SurfaceMesh& mesh, double E, double nu, const Eigen::VectorXd& u,
                                 const Eigen::VectorXd& q, const StressEvaluationSettings& settings)
    : mesh_(mesh),
      E_(E),
      nu_(nu),
      u_(u),
      q_(q),
      settings_(settings),
      surface_(surfaceStresses(mesh, E, nu, u, q)) {}

void StressEvaluator::addCracks(const CrackMesh& cracks, const Eigen::VectorXd& nodalOpenings) {
    cracks_ = &cracks;
    openings_ = &nodalOpenings;
}

Eigen::Matrix3d StressEvaluator::interiorStress(const Eigen::Vector3d& x) const {
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    for (int t = 0; t < mesh_.triangleCount(); ++t) {
        const auto& tri = mesh_.triangle(t);
        SubTriangle s{{mesh_.node(tri[0]), mesh_.node(tri[1]), mesh_.node(tri[2])},
                      {u_.segment<3>(3 * tri[0]), u_.segment<3>(3 * tri[1]), u_.segment<3>(3 * tri[2])},
                      mesh_.area(t)};
        integrateAdaptive(x, s, mesh_.normal(t), q_.segment<3>(3 * t), E_, nu_, settings_, 0, sigma);
    }
    if (cracks_)
        for (int t = 0; t < cracks_->triangleCount(); ++t) {
            const auto& tri = cracks_->triangle(t);
            const Eigen::VectorXd& cod = *openings_;
            SubTriangle s{
                {cracks_->node(tri[0]), cracks_->node(tri[1]), cracks_->node(tri[2])},
                {cod.segment<3>(3 * tri[0]), cod.segment<3>(3 * tri[1]), cod.segment<3>(3 * tri[2])},
                cracks_->area(t)};
            integrateAdaptive(x, s, -cracks_->normal(t), Eigen::Vector3d::Zero(), E_, nu_, settings_, 0,
                              sigma);
        }
    sigma.triangularView<Eigen::StrictlyLower>() = sigma.transpose().triangularView<Eigen::StrictlyLower>();
    return sigma;
}

Eigen::Matrix3d StressEvaluator::nearestSurfaceStress(const Eigen::Vector3d& x) const {
    return surface_[mesh_.nearest(x).triangle];
}

Eigen::Matrix3d StressEvaluator::stressAt(const Eigen::Vector3d& x) const {
    const SurfaceMesh::Nearest near = mesh_.nearest(x);
    const double h = mesh_.diameter(near.triangle);
    const double s =
        (near.distance / h - settings_.nearFraction) / (settings_.farFraction - settings_.nearFraction);
    if (s <= 0.0) return surface_[near.triangle];
    const Eigen::Matrix3d interior = interiorStress(x);
    if (s >= 1.0) return interior;
    const double w = s * s * (3.0 - 2.0 * s);  // smoothstep
    return w * interior + (1.0 - w) * surface_[near.triangle];
}

}  // namespace btfracture
