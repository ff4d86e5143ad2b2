// SPDX-License-Identifier: Zlib
#include <btFracture/core/Material.h>

#include <btFracture/core/Error.h>

#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

void requirePositive(const std::string& material, const char* field, const char* unit, double value) {
    if (!std::isfinite(value) || value <= 0.0) {
        std::ostringstream msg;
        msg << "material '" << material << "': " << field << " must be positive and finite, got " << value
            << " " << unit;
        throw Error(msg.str());
    }
}

}  // namespace

Material::Material(double youngsModulus, double poissonRatio, double density, double tensileStrength,
                   double fractureToughness, double compressiveFactor, std::string name)
    : name_(std::move(name)),
      youngsModulus_(youngsModulus),
      poissonRatio_(poissonRatio),
      density_(density),
      tensileStrength_(tensileStrength),
      fractureToughness_(fractureToughness),
      compressiveFactor_(compressiveFactor) {
    requirePositive(name_, "Young's modulus E", "Pa", youngsModulus);
    if (!std::isfinite(poissonRatio) || poissonRatio <= -1.0 || poissonRatio >= 0.5) {
        std::ostringstream msg;
        msg << "material '" << name_ << "': Poisson ratio nu must lie in (-1, 0.5), got " << poissonRatio;
        throw Error(msg.str());
    }
    requirePositive(name_, "density", "kg/m^3", density);
    requirePositive(name_, "tensile strength", "Pa", tensileStrength);
    requirePositive(name_, "fracture toughness", "Pa m^(1/2)", fractureToughness);
    requirePositive(name_, "compressive factor", "(ratio)", compressiveFactor);
}

// Soda-lime glass: E 70 GPa, nu 0.22, rho 2500 (Ashby & Jones, Engineering Materials 1, table 3.1);
// K_Ic 0.75 MPa m^1/2 (same source, ch. 13); practical tensile strength of annealed glass ~50 MPa;
// compressive strength ~1 GPa, so the compressive factor is about 20.
Material Material::glass() {
    return Material(70e9, 0.22, 2500.0, 50e6, 0.75e6, 20.0, "glass");
}

// Normal-strength concrete: E 30 GPa, nu 0.2, rho 2400 (Eurocode 2, C30/37), tensile strength
// ~3 MPa (f_ctm of C30/37 is 2.9 MPa), K_Ic ~1 MPa m^1/2 (Bazant & Planas), compressive
// strength 30 MPa, so a factor of 10.
Material Material::concrete() {
    return Material(30e9, 0.2, 2400.0, 3e6, 1.0e6, 10.0, "concrete");
}

// The authors' PMMA-like plastic (FractureBEM edge_crack example): E 3.1 GPa, nu 0.327,
// rho 1200, strength 76 MPa, K_c 1 MPa m^1/2; compressive strength of PMMA ~124 MPa, so 1.6.
Material Material::pmma() {
    return Material(3.1e9, 0.327, 1200.0, 76e6, 1.0e6, 1.6, "pmma");
}

// Structural steel: E 210 GPa, nu 0.3, rho 7850 (EN 1993-1-1 3.2.6), yield-level strength
// 355 MPa, K_Ic ~50 MPa m^1/2; used for bodies that are not meant to break.
Material Material::steel() {
    return Material(210e9, 0.3, 7850.0, 355e6, 50e6, 1.0, "steel");
}

std::vector<std::string> Material::presetNames() {
    return {"glass", "concrete", "pmma", "steel"};
}

Material Material::preset(const std::string& name) {
    if (name == "glass") return glass();
    if (name == "concrete") return concrete();
    if (name == "pmma") return pmma();
    if (name == "steel") return steel();
    std::ostringstream msg;
    msg << "unknown material preset '" << name << "'; known presets:";
    for (const auto& known : presetNames()) msg << " " << known;
    throw Error(msg.str());
}

double Material::shearModulus() const {
    return youngsModulus_ / (2.0 * (1.0 + poissonRatio_));
}

double Material::lameLambda() const {
    return youngsModulus_ * poissonRatio_ / ((1.0 + poissonRatio_) * (1.0 - 2.0 * poissonRatio_));
}

double Material::planeStrainModulus() const {
    return youngsModulus_ / (1.0 - poissonRatio_ * poissonRatio_);
}

double Material::rayleighWaveSpeed() const {
    return (0.862 + 1.14 * poissonRatio_) / (1.0 + poissonRatio_) * std::sqrt(shearModulus() / density_);
}

}  // namespace btfracture
