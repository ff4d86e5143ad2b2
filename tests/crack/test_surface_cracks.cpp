// SPDX-License-Identifier: Zlib
// The surface-breaking reference cracks of bench/sif_validation: their handbook values against
// the published tables, and the meshes they are solved on.
#include <btFracture/fracture/ReferenceCracks.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace btfracture;

TEST(SurfaceCrackCases, HandbookValuesMatchThePublishedTables) {
    // Tada, Paris & Irwin, The Stress Analysis of Cracks Handbook (2000), 2.10: F(0.2) = 1.37,
    // F(0.4) = 2.11 (two decimals); ASTM E399 tabulates f(0.5) = 2.66 for the notched beam.
    for (const auto& [ratio, F] : {std::pair{0.2, 1.37}, std::pair{0.4, 2.11}}) {
        const SurfaceCrackCase c = edgeCrackCase(ratio, 2);
        const double a = ratio * 0.1;
        EXPECT_NEAR(c.exactKI / (1e6 * std::sqrt(M_PI * a)), F, 0.006) << c.name;
    }
    const SurfaceCrackCase beam = notchedBeamCase(2);
    EXPECT_NEAR(beam.exactKI * 0.05 * std::pow(0.1, 1.5) / (1e4 * 0.4), 2.66, 0.006);
}

TEST(SurfaceCrackCases, SheetsReachTheSurfaceAndLoadsBalance) {
    // The sheet starts on the body's surface and its front is inside; the beam's patch loads
    // carry no net force or torque.
    for (const SurfaceCrackCase& c : {edgeCrackCase(0.2, 4, 0.0), notchedBeamCase(4, 0.0)}) {
        const SurfaceMesh mesh(c.body);
        const Eigen::Vector3d mouth = c.origin + c.along.front() * c.U - mesh.offset();
        EXPECT_LT(mesh.nearest(mouth).distance, 1e-12) << c.name;
        EXPECT_TRUE(mesh.encloses(c.midFront - mesh.offset())) << c.name;
        const Eigen::VectorXd q = c.tractions(mesh);
        Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
        double scale = 0.0;
        for (int t = 0; t < mesh.triangleCount(); ++t) {
            const Eigen::Vector3d f = mesh.area(t) * q.segment<3>(3 * t);
            force += f;
            torque += mesh.centroid(t).cross(f);
            scale += f.norm();
        }
        EXPECT_LT(force.norm(), 1e-9 * scale) << c.name;
        EXPECT_LT(torque.norm(), 1e-9 * scale * mesh.radius()) << c.name;
    }
}
