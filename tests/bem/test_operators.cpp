// SPDX-License-Identifier: Zlib
// Galerkin operators: symmetry, rigid-body null space, the Kupradze form of the double layer
// behind F, and bit-identical parallel assembly.
#include <btFracture/bem/BoundaryOperators.h>
#include <btFracture/bem/Quadrature.h>
#include <btFracture/bem/RigidModes.h>
#include <btFracture/core/CrossMatrix.h>
#include <btFracture/core/Primitives.h>

#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace btfracture;

namespace {

const ElasticConstants kSteelLike{80e9, 0.3};

// A non-convex, non-symmetric closed test body: a box with one corner pulled out.
TriangleMesh skewedBox() {
    TriangleMesh mesh = makeBox({0.6, 0.4, 0.3}, 4, 3, 2);
    for (auto& v : mesh.vertices)
        v += 0.15 * Eigen::Vector3d(v.y() * v.z(), 0.5 * v.x() * v.x(), 0.3 * v.x() * v.y());
    return mesh;
}

// Kelvin solution U*(x, y) [m/N].
Eigen::Matrix3d kelvin(const Eigen::Vector3d& x, const Eigen::Vector3d& y, const ElasticConstants& c) {
    const Eigen::Vector3d d = y - x;
    const double r = d.norm();
    return ((3.0 - 4.0 * c.poissonRatio) / r * Eigen::Matrix3d::Identity() +
            d * d.transpose() / (r * r * r)) /
           (16.0 * M_PI * c.shearModulus * (1.0 - c.poissonRatio));
}

// Row k: traction at y (normal n) of the Kelvin field of a unit force e_k at x, from the
// analytic gradient of U* and Hooke's law.
Eigen::Matrix3d kelvinTraction(const Eigen::Vector3d& x, const Eigen::Vector3d& y, const Eigen::Vector3d& n,
                               const ElasticConstants& c) {
    const double mu = c.shearModulus, nu = c.poissonRatio, lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
    const Eigen::Vector3d d = y - x;
    const double r = d.norm(), r3 = r * r * r, r5 = r3 * r * r;
    const double scale = 1.0 / (16.0 * M_PI * mu * (1.0 - nu));
    Eigen::Matrix3d out;
    for (int k = 0; k < 3; ++k) {
        Eigen::Matrix3d grad;  // grad(i, m) = d u_i / d y_m of the field u = U* e_k
        for (int i = 0; i < 3; ++i)
            for (int m = 0; m < 3; ++m)
                grad(i, m) =
                    scale * (-(3.0 - 4.0 * nu) * (i == k) * d[m] / r3 +
                             ((i == m) * d[k] + (k == m) * d[i]) / r3 - 3.0 * d[i] * d[k] * d[m] / r5);
        const Eigen::Matrix3d sigma =
            lambda * grad.trace() * Eigen::Matrix3d::Identity() + mu * (grad + grad.transpose());
        out.row(k) = (sigma * n).transpose();
    }
    return out;
}

}  // namespace

TEST(BoundaryOperators, StiffnessIsSymmetricWithRigidNullSpace) {
    const SurfaceMesh mesh(skewedBox());
    const BoundaryOperators ops = assembleBoundaryOperators(mesh, kSteelLike);
    const Eigen::MatrixXd& K = ops.stiffness;
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff() / scale, 1e-10);

    const Eigen::MatrixXd R = rigidMotions(mesh);
    for (int mode = 0; mode < 6; ++mode) {
        const double residual = (K * R.col(mode)).norm() / (K.norm() * R.col(mode).norm());
        // Translations vanish exactly (curls of constants are zero); rotations to quadrature accuracy.
        EXPECT_LT(residual, mode < 3 ? 1e-8 : 1e-6) << "rigid mode " << mode;
    }
    // Positive semi-definite with exactly six (near-)zero eigenvalues: the rigid motions.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
    const double largest = eig.eigenvalues().maxCoeff();
    for (int i = 0; i < 6; ++i)
        EXPECT_LT(std::abs(eig.eigenvalues()(i)), 1e-5 * largest) << "eigenvalue " << i;
    EXPECT_GT(eig.eigenvalues()(6), 1e-4 * largest);
}

TEST(BoundaryOperators, KupradzeFormOfDoubleLayerMatchesKelvinTraction) {
    // F uses (K v)(x) = K_Laplace v - V_Laplace(M v) + 2 mu V_Lame(M v) with M v = sum_a c_a x v_a.
    // Off the surface every integral is regular, so both sides converge to ~1e-10 with a high
    // rule; a sign or transpose slip shows up at order one.
    const SurfaceMesh mesh(skewedBox());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd v(3 * mesh.nodeCount());
    for (int i = 0; i < v.size(); ++i) v[i] = uniform(rng);
    const TriangleRule& rule = triangleRule(20);
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.1, -0.05, 0.02), Eigen::Vector3d(1.4, 0.7, -0.9)}) {
        Eigen::Vector3d direct = Eigen::Vector3d::Zero(), kupradze = Eigen::Vector3d::Zero();
        for (int t = 0; t < mesh.triangleCount(); ++t) {
            const auto& tri = mesh.triangle(t);
            Eigen::Vector3d curlV = Eigen::Vector3d::Zero();  // M v on this triangle
            for (int a = 0; a < 3; ++a) curlV += mesh.hatCurl(t, a).cross(v.segment<3>(3 * tri[a]));
            for (const auto& p : rule.points) {
                const double l[3] = {p.l0, p.l1, p.l2};
                Eigen::Vector3d y = Eigen::Vector3d::Zero(), vy = Eigen::Vector3d::Zero();
                for (int a = 0; a < 3; ++a) {
                    y += l[a] * mesh.node(tri[a]);
                    vy += l[a] * v.segment<3>(3 * tri[a]);
                }
                const double w = p.w * mesh.area(t);
                direct += w * kelvinTraction(x, y, mesh.normal(t), kSteelLike) * vy;
                const Eigen::Vector3d d = x - y;
                const double r = d.norm();
                kupradze +=
                    w * (d.dot(mesh.normal(t)) / (4.0 * M_PI * r * r * r) * vy - curlV / (4.0 * M_PI * r) +
                         2.0 * kSteelLike.shearModulus * kelvin(x, y, kSteelLike) * curlV);
            }
        }
        EXPECT_LT((direct - kupradze).norm(), 1e-8 * direct.norm())
            << direct.transpose() << " vs " << kupradze.transpose();
    }
}

TEST(BoundaryOperators, BalancedTractionsLoadNoRigidMotion) {
    // <F q, r> = <q, r> for rigid r, which vanishes for balanced q; checks the 1/2 M term's sign.
    const SurfaceMesh mesh(makeGeodesicSphere(0.5, 4));
    const BoundaryOperators ops = assembleBoundaryOperators(mesh, kSteelLike);
    const Eigen::MatrixXd R = rigidMotions(mesh);
    Eigen::VectorXd q(3 * mesh.triangleCount());
    for (int t = 0; t < mesh.triangleCount(); ++t) q.segment<3>(3 * t) = -1e6 * mesh.normal(t);  // pressure
    const Eigen::VectorXd f = ops.tractionToLoad * q;
    EXPECT_LT((R.transpose() * f).norm(), 1e-6 * f.norm() * R.norm());
    // An unbalanced load (uniform pull along x) does load the translation mode: <q, e_x> = area * 1e6.
    for (int t = 0; t < mesh.triangleCount(); ++t) q.segment<3>(3 * t) = Eigen::Vector3d(1e6, 0, 0);
    const double loadX = R.col(0).dot(ops.tractionToLoad * q);
    EXPECT_NEAR(loadX / (1e6 * mesh.surfaceArea()), 1.0, 1e-5);
}

TEST(BoundaryOperators, AssemblyIsBitIdenticalForAnyThreadCount) {
    const SurfaceMesh mesh(skewedBox());
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const BoundaryOperators serial = assembleBoundaryOperators(mesh, kSteelLike);
    omp_set_num_threads(std::max(2, saved));
    const BoundaryOperators parallel = assembleBoundaryOperators(mesh, kSteelLike);
    omp_set_num_threads(saved);
    EXPECT_EQ((serial.stiffness - parallel.stiffness).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((serial.tractionToLoad - parallel.tractionToLoad).cwiseAbs().maxCoeff(), 0.0);
}
