// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/dynamics/TractionBalance.h>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <random>

using namespace btfracture;

namespace {

// Unit-ish ellipsoid-like closed mesh: a UV sphere scaled per axis, centred at the origin.
TriangleMesh ellipsoid(int rings, int segments, const Eigen::Vector3d& radii) {
    TriangleMesh m;
    m.name = "ellipsoid";
    m.vertices.push_back(Eigen::Vector3d(0, 0, radii.z()));
    for (int r = 1; r < rings; ++r) {
        const double theta = M_PI * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = 2.0 * M_PI * s / segments;
            m.vertices.push_back(Eigen::Vector3d(radii.x() * std::sin(theta) * std::cos(phi),
                                                 radii.y() * std::sin(theta) * std::sin(phi),
                                                 radii.z() * std::cos(theta)));
        }
    }
    m.vertices.push_back(Eigen::Vector3d(0, 0, -radii.z()));
    const int south = static_cast<int>(m.vertices.size()) - 1;
    auto ring = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            m.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
            m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
        }
    for (int s = 0; s < segments; ++s)
        m.triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
    return m;
}

TractionField randomField(std::size_t n, unsigned seed, double scale) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    TractionField q(n);
    for (auto& t : q) t = scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
    return q;
}

// The dense constraint matrix A (6 x 3n) of Eq. 6 for brute-force checks.
Eigen::MatrixXd denseConstraints(const TractionBalancer& b) {
    const std::size_t n = b.areas().size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 3 * n);
    for (std::size_t e = 0; e < n; ++e) {
        const Eigen::Vector3d& c = b.centroids()[e];
        Eigen::Matrix3d cross;
        cross << 0, -c.z(), c.y(), c.z(), 0, -c.x(), -c.y(), c.x(), 0;
        A.block<3, 3>(0, 3 * e) = b.areas()[e] * Eigen::Matrix3d::Identity();
        A.block<3, 3>(3, 3 * e) = b.areas()[e] * cross;
    }
    return A;
}

Eigen::VectorXd flatten(const TractionField& q) {
    Eigen::VectorXd v(3 * q.size());
    for (std::size_t e = 0; e < q.size(); ++e) v.segment<3>(3 * e) = q[e];
    return v;
}

}  // namespace

TEST(TractionBalance, BalancedFieldHasNoNetForceOrTorque) {
    // Off-centre mesh too: torque is about the origin whatever the mesh position.
    for (const Eigen::Vector3d& shift : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, -0.2, 0.1)}) {
        TriangleMesh mesh = ellipsoid(12, 24, Eigen::Vector3d(0.3, 0.1, 0.2));
        for (auto& v : mesh.vertices) v += shift;
        const TractionBalancer balancer(mesh);
        const TractionField q = randomField(mesh.triangles.size(), 7, 1e6);
        const NetLoad before = balancer.netLoad(q);
        ASSERT_GT(before.force.norm(), 1e-3 * before.forceScale);  // the test field is unbalanced
        const TractionField balanced = balancer.balance(q);
        const NetLoad after = balancer.netLoad(balanced);
        EXPECT_LT(after.force.norm(), 1e-10 * after.forceScale) << after.force.transpose();
        EXPECT_LT(after.torque.norm(), 1e-10 * after.torqueScale) << after.torque.transpose();
    }
}

TEST(TractionBalance, CorrectionIsTheMinimumNormProjection) {
    const TriangleMesh mesh = ellipsoid(8, 12, Eigen::Vector3d(0.2, 0.15, 0.1));
    const TractionBalancer balancer(mesh);
    const TractionField q = randomField(mesh.triangles.size(), 11, 1e5);
    const Eigen::VectorXd balanced = flatten(balancer.balance(q));

    // Brute force: orthogonal projection onto the null space of the dense A via SVD.
    const Eigen::MatrixXd A = denseConstraints(balancer);
    const Eigen::VectorXd qi = flatten(q);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd projected = qi - svd.solve(A * qi);
    EXPECT_LT((balanced - projected).norm(), 1e-10 * qi.norm());

    // Minimality: no other balanced field (balanced + null-space perturbation) is closer.
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    const double best = (qi - balanced).norm();
    for (int trial = 0; trial < 20; ++trial) {
        Eigen::VectorXd delta(qi.size());
        for (Eigen::Index i = 0; i < delta.size(); ++i) delta(i) = g(rng);
        delta -= svd.solve(A * delta);  // keep it balanced
        delta *= 1e3 / delta.norm();
        EXPECT_GT((qi - (balanced + delta)).norm(), best);
    }
}

TEST(TractionBalance, BalancedFieldIsUnchanged) {
    const TriangleMesh mesh = ellipsoid(10, 16, Eigen::Vector3d(0.1, 0.1, 0.1));
    const TractionBalancer balancer(mesh);
    const TractionField balanced = balancer.balance(randomField(mesh.triangles.size(), 5, 2e6));
    const TractionField again = balancer.balance(balanced);
    double diff = 0.0, norm = 0.0;
    for (std::size_t e = 0; e < balanced.size(); ++e) {
        diff = std::max(diff, (again[e] - balanced[e]).norm());
        norm = std::max(norm, balanced[e].norm());
    }
    EXPECT_LT(diff, 1e-12 * norm);
    // A uniform pressure on a closed surface is self-equilibrated and stays as it is.
    TractionField pressure(mesh.triangles.size());
    for (std::size_t e = 0; e < pressure.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const Eigen::Vector3d n =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        pressure[e] = -1e5 * n.normalized();
    }
    const TractionField kept = balancer.balance(pressure);
    for (std::size_t e = 0; e < pressure.size(); ++e) EXPECT_LT((kept[e] - pressure[e]).norm(), 1e-9 * 1e5);
}

TEST(TractionBalance, ContactGoesToClosestTriangleNotClosestCentroid) {
    // The query point lies on the long triangle 0, whose centroid is far away; the nearest centroid
    // belongs to triangle 3 (in the plane x = 0), 0.42 away.
    TriangleMesh mesh;
    mesh.name = "two triangles";
    mesh.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 1, 0}, {0, 3, 0}, {1, 3, 0}, {0, 4, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    mesh.vertices.push_back({0, 0, 1});  // off-plane vertex so that A A^T is not singular
    mesh.triangles.push_back({0, 6, 1});
    mesh.triangles.push_back({0, 2, 6});
    const TractionBalancer balancer(mesh);
    const Eigen::Vector3d p(0.2, 0.5, 0.0);
    EXPECT_EQ(balancer.closestSurfacePoint(p).triangle, 0);
    EXPECT_NEAR(balancer.closestSurfacePoint(p).distance, 0.0, 1e-15);

    BodyContact contact;
    contact.point = p + Eigen::Vector3d(0, 0, 1e-3);
    contact.direction = Eigen::Vector3d(0, 0, -2);  // normalised inside
    contact.impulse = 0.5;
    contact.duration = 1e-4;
    const TractionField q = balancer.contactTractions({contact});
    const double area = 5.0;  // triangle 0: 10 x 1 / 2
    EXPECT_NEAR(q[0].z(), -0.5 / (1e-4 * area), 1e-9);
    EXPECT_EQ(q[1], Eigen::Vector3d::Zero());

    contact.duration = 0.0;
    EXPECT_THROW(balancer.contactTractions({contact}), Error);
}

TEST(TractionBalance, SingularSystemIsExplained) {
    // All centroids on the x axis: the torque about x cannot be controlled.
    TriangleMesh mesh;
    mesh.name = "needle";
    mesh.vertices = {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 1}, {4, 0, -1}, {5, 0, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    try {
        TractionBalancer balancer(mesh);
        FAIL() << "expected an Error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("needle"), std::string::npos) << what;
        EXPECT_NE(what.find("singular"), std::string::npos) << what;
        EXPECT_NE(what.find("one line through the origin"), std::string::npos) << what;
    }
    EXPECT_THROW(TractionBalancer(TriangleMesh{}), Error);
}
