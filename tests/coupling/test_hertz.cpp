// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/dynamics/HertzContact.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace btfracture;

namespace {

// validation.md (e): two steel balls of radius 10 mm (E 210 GPa, nu 0.3, density 7850) at 1 m/s.
// "10 mm" is the radius: with it the formulas give t_c = 60.16 us and F_max = 1005.4 N, the
// acceptance values; a 10 mm diameter would give 30.1 us and 251 N.
HertzBody steelBall() {
    const double radius = 0.01;
    const double mass = 7850.0 * 4.0 / 3.0 * M_PI * radius * radius * radius;
    return HertzBody{210e9, 0.3, 1.0 / mass, 1.0 / radius};
}

}  // namespace

TEST(Hertz, TwoSteelBallsMatchValidationValues) {
    const HertzImpact h = hertzImpact(steelBall(), steelBall(), 1.0, 1.0);
    EXPECT_NEAR(h.contactDuration, 60.2e-6, 60.2e-6 * 1e-3) << h.contactDuration;
    EXPECT_NEAR(h.peakForce, 1005.0, 1005.0 * 1e-3) << h.peakForce;
    EXPECT_FALSE(h.speedFloored);
    EXPECT_FALSE(h.radiusCapped);
    EXPECT_NEAR(h.effectiveRadius, 0.005, 1e-15);
    EXPECT_NEAR(h.effectiveModulus, 210e9 / (2.0 * 0.91), 1.0);
    // Consistency with the approach alpha* = (15 m v^2 / (16 E sqrt R))^(2/5): t_c = 2.9432 alpha*/v.
    const double alpha =
        std::pow(15.0 * h.effectiveMass / (16.0 * h.effectiveModulus * std::sqrt(h.effectiveRadius)), 0.4);
    EXPECT_NEAR(alpha, 20.4e-6, 0.05e-6);
    EXPECT_NEAR(h.contactDuration, 2.9432 * alpha, 1e-4 * h.contactDuration);
}

TEST(Hertz, ScalingWithSpeedAndSymmetry) {
    const HertzImpact slow = hertzImpact(steelBall(), steelBall(), 1.0, 1.0);
    const HertzImpact fast = hertzImpact(steelBall(), steelBall(), 32.0, 1.0);
    EXPECT_NEAR(fast.contactDuration / slow.contactDuration, 0.5, 1e-12);  // v^(-1/5)
    EXPECT_NEAR(fast.peakForce / slow.peakForce, std::pow(32.0, 1.2), 1e-9);
    HertzBody plate{70e9, 0.22, 0.0, 0.0};
    const HertzImpact ab = hertzImpact(steelBall(), plate, 2.0, 1.0);
    const HertzImpact ba = hertzImpact(plate, steelBall(), 2.0, 1.0);
    EXPECT_EQ(ab.contactDuration, ba.contactDuration);
    // Ball on a static flat plate: m* = m, R* = R.
    EXPECT_NEAR(ab.effectiveMass, 1.0 / steelBall().inverseMass, 1e-15);
    EXPECT_NEAR(ab.effectiveRadius, 0.01, 1e-15);
}

TEST(Hertz, LimitsAreFiniteAndPositive) {
    const HertzBody flatBlock{210e9, 0.3, 1.0, 0.0};
    const HertzBody ground{210e9, 0.3, 0.0, 0.0};
    for (double speed : {0.0, 1e-12, 1e-6, 1e-3, 1.0, 1e3}) {
        // Flat on flat: R* = inf without the cap.
        const HertzImpact h = hertzImpact(flatBlock, ground, speed, 0.1);
        EXPECT_TRUE(std::isfinite(h.contactDuration) && h.contactDuration > 0.0) << speed;
        EXPECT_TRUE(std::isfinite(h.peakForce) && h.peakForce > 0.0) << speed;
        EXPECT_TRUE(h.radiusCapped);
        EXPECT_EQ(h.effectiveRadius, 0.1);
        EXPECT_EQ(h.speedFloored, speed < kMinApproachSpeed);
        EXPECT_GE(h.approachSpeed, kMinApproachSpeed);
    }
    // The floor: v -> 0 gives the duration at kMinApproachSpeed, not infinity.
    EXPECT_EQ(hertzImpact(flatBlock, ground, 0.0, 0.1).contactDuration,
              hertzImpact(flatBlock, ground, kMinApproachSpeed, 0.1).contactDuration);
    // Concave curvature counts as flat.
    HertzBody concave = flatBlock;
    concave.curvature = -50.0;
    EXPECT_EQ(hertzImpact(concave, ground, 1.0, 0.1).contactDuration,
              hertzImpact(flatBlock, ground, 1.0, 0.1).contactDuration);
    // Slight curvature below 1/cap is capped too.
    HertzBody gentle = flatBlock;
    gentle.curvature = 5.0;
    EXPECT_EQ(hertzImpact(gentle, ground, 1.0, 0.1).effectiveRadius, 0.1);
}

TEST(Hertz, BadInputThrowsNamingTheValue) {
    const HertzBody ball = steelBall();
    HertzBody bad = ball;
    bad.youngsModulus = -1.0;
    try {
        hertzImpact(bad, ball, 1.0, 1.0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("Young's modulus -1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(hertzImpact(ball, ball, NAN, 1.0), Error);
    EXPECT_THROW(hertzImpact(ball, ball, 1.0, 0.0), Error);
    EXPECT_THROW(hertzImpact(ball, ball, -1.0, 1.0), Error);
    const HertzBody wall{210e9, 0.3, 0.0, 0.0};
    EXPECT_THROW(hertzImpact(wall, wall, 1.0, 1.0), Error);
    bad = ball;
    bad.poissonRatio = 0.5;
    EXPECT_THROW(hertzImpact(ball, bad, 1.0, 1.0), Error);
}
