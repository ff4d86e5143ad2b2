// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/Primitives.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace btfracture;

TEST(Primitives, BoxIsClosedWithExactVolume) {
    const TriangleMesh box = makeBox({0.5, 0.3, 0.2}, 5, 3, 2);
    const MeshDefects d = inspectMesh(box);
    EXPECT_TRUE(d.isClosedManifold()) << d.describe();
    EXPECT_EQ(box.triangles.size(), 2u * 2 * (5 * 3 + 3 * 2 + 2 * 5));
    EXPECT_NEAR(computeMassProperties(box).volume, 1.0 * 0.6 * 0.4, 1e-14);
}

TEST(Primitives, GeodesicSphereConvergesToTheBall) {
    double previous = 1.0;
    for (int f : {2, 4, 8, 16}) {
        const TriangleMesh s = makeGeodesicSphere(2.0, f);
        const MeshDefects d = inspectMesh(s);
        EXPECT_TRUE(d.isClosedManifold()) << d.describe();
        EXPECT_EQ(s.triangles.size(), 20u * f * f);
        EXPECT_EQ(s.vertices.size(), 10u * f * f + 2);
        const double error = 1.0 - computeMassProperties(s).volume / (4.0 / 3.0 * M_PI * 8.0);
        EXPECT_GT(error, 0.0);             // inscribed
        EXPECT_LT(error, previous / 3.5);  // second order: error / 4 per halving of h
        previous = error;
    }
}

TEST(Primitives, TorusIsClosedAndConvergesToItsVolume) {
    // Exact volume 2 pi^2 R r^2; the inscribed polyhedron's error falls as h^2.
    const double R = 0.3, r = 0.1, exact = 2.0 * M_PI * M_PI * R * r * r;
    double previous = 1.0;
    for (int n : {12, 24, 48}) {
        const TriangleMesh t = makeTorus(R, r, 2 * n, n);
        const MeshDefects d = inspectMesh(t);
        EXPECT_TRUE(d.isClosedManifold()) << d.describe();
        EXPECT_EQ(t.triangles.size(), 4u * n * n);
        const double error = 1.0 - computeMassProperties(t).volume / exact;
        EXPECT_GT(error, 0.0);
        EXPECT_LT(error, previous / 3.5);
        previous = error;
    }
    EXPECT_THROW(makeTorus(0.1, 0.2, 8, 8), Error);
    EXPECT_THROW(makeTorus(0.3, 0.1, 2, 8), Error);
}
