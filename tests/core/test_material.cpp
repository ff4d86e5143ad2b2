// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/Material.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using btfracture::Error;
using btfracture::Material;

namespace {

// Runs `make` and returns the error message it throws (empty if it does not throw).
template <class F>
std::string errorOf(F make) {
    try {
        make();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(Material, DerivedModuliOfPmmaPreset) {
    const Material m = Material::pmma();
    EXPECT_DOUBLE_EQ(m.youngsModulus(), 3.1e9);
    EXPECT_DOUBLE_EQ(m.poissonRatio(), 0.327);
    // mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu))
    EXPECT_NEAR(m.shearModulus(), 3.1e9 / 2.654, 1e-3);
    EXPECT_NEAR(m.lameLambda(), 3.1e9 * 0.327 / (1.327 * 0.346), 1e-3);
    EXPECT_NEAR(m.planeStrainModulus(), 3.1e9 / (1 - 0.327 * 0.327), 1e-3);
    // Rayleigh speed lies just below the shear wave speed.
    const double cs = std::sqrt(m.shearModulus() / m.density());
    EXPECT_GT(m.rayleighWaveSpeed(), 0.87 * cs);
    EXPECT_LT(m.rayleighWaveSpeed(), 0.96 * cs);
}

TEST(Material, EveryPresetIsValidAndFoundByName) {
    for (const auto& name : Material::presetNames()) {
        const Material m = Material::preset(name);
        EXPECT_EQ(m.name(), name);
        EXPECT_GT(m.youngsModulus(), 0.0);
    }
    const std::string message = errorOf([] { Material::preset("unobtainium"); });
    EXPECT_NE(message.find("unobtainium"), std::string::npos) << message;
    EXPECT_NE(message.find("glass"), std::string::npos) << message;
}

TEST(Material, RejectsBadConstantsNamingFieldAndValue) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
        double E, nu, rho, strength, toughness, factor;
        const char* field;
        const char* value;
    };
    const Case cases[] = {
        {0.0, 0.3, 1000, 1e6, 1e6, 2, "Young's modulus", "0"},
        {-5e9, 0.3, 1000, 1e6, 1e6, 2, "Young's modulus", "-5e+09"},
        {1e9, 0.5, 1000, 1e6, 1e6, 2, "Poisson ratio", "0.5"},
        {1e9, -1.0, 1000, 1e6, 1e6, 2, "Poisson ratio", "-1"},
        {1e9, nan, 1000, 1e6, 1e6, 2, "Poisson ratio", "nan"},
        {1e9, 0.3, 0.0, 1e6, 1e6, 2, "density", "0"},
        {1e9, 0.3, -2.0, 1e6, 1e6, 2, "density", "-2"},
        {1e9, 0.3, 1000, -1.0, 1e6, 2, "tensile strength", "-1"},
        {1e9, 0.3, 1000, 1e6, 0.0, 2, "fracture toughness", "0"},
        {1e9, 0.3, 1000, 1e6, 1e6, std::numeric_limits<double>::infinity(), "compressive factor", "inf"},
    };
    for (const Case& c : cases) {
        const std::string message =
            errorOf([&] { Material(c.E, c.nu, c.rho, c.strength, c.toughness, c.factor, "probe"); });
        EXPECT_NE(message.find(c.field), std::string::npos) << message;
        EXPECT_NE(message.find(c.value), std::string::npos) << message;
        EXPECT_NE(message.find("probe"), std::string::npos) << message;
    }
}
