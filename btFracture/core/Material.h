// SPDX-License-Identifier: Zlib
#pragma once
// Isotropic linear elastic, brittle material in SI units, validated on construction.
#include <string>
#include <vector>

namespace btfracture {

class Material {
public:
    // Throws btfracture::Error naming the field and value when a constant is out of range:
    // E > 0, -1 < nu < 0.5, density > 0, strength > 0, toughness > 0, compressive factor > 0,
    // all finite.
    Material(double youngsModulus, double poissonRatio, double density, double tensileStrength,
             double fractureToughness, double compressiveFactor, std::string name = "custom");

    // Named presets (typical handbook values; sources in Material.cpp).
    static Material glass();
    static Material concrete();
    static Material pmma();   // the authors' PMMA-like plastic: E 3.1 GPa, nu 0.327
    static Material steel();  // stiff default for bodies that never break
    // Looks a preset up by name ("glass", "concrete", "pmma", "steel"); throws on unknown names.
    static Material preset(const std::string& name);
    static std::vector<std::string> presetNames();

    const std::string& name() const { return name_; }
    double youngsModulus() const { return youngsModulus_; }          // E [Pa]
    double poissonRatio() const { return poissonRatio_; }            // nu [-]
    double density() const { return density_; }                      // rho [kg/m^3]
    double tensileStrength() const { return tensileStrength_; }      // [Pa]
    double fractureToughness() const { return fractureToughness_; }  // K_Ic [Pa m^(1/2)]
    // Compressive strength and toughness as a multiple of the tensile ones [-].
    double compressiveFactor() const { return compressiveFactor_; }

    double shearModulus() const;        // mu = E / (2 (1 + nu)) [Pa]
    double lameLambda() const;          // lambda = E nu / ((1 + nu)(1 - 2 nu)) [Pa]
    double planeStrainModulus() const;  // E' = E / (1 - nu^2) [Pa]
    // Rayleigh wave speed c_R [m/s], Viktorov's approximation (0.862 + 1.14 nu)/(1 + nu) sqrt(mu/rho).
    double rayleighWaveSpeed() const;

private:
    std::string name_;
    double youngsModulus_;
    double poissonRatio_;
    double density_;
    double tensileStrength_;
    double fractureToughness_;
    double compressiveFactor_;
};

}  // namespace btfracture
