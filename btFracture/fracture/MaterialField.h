// SPDX-License-Identifier: Zlib
#pragma once
// Strength and toughness as functions of position: the material's constants, optionally
// varied by seeded smooth noise (paper §3, "high-frequency spatial variations"; default off).
#include <btFracture/core/FractureSettings.h>
#include <btFracture/core/Material.h>

#include <Eigen/Core>

namespace btfracture {

class MaterialField {
public:
    MaterialField(const Material& material, const MaterialNoise& noise = {});
    const Material& material() const { return material_; }
    double tensileStrength(const Eigen::Vector3d& x) const;    // [Pa]
    double fractureToughness(const Eigen::Vector3d& x) const;  // [Pa m^(1/2)]
    // The common factor 1 + amplitude (2 n(x) - 1), n in [0, 1]; 1 without noise.
    double variation(const Eigen::Vector3d& x) const;

private:
    Material material_;
    MaterialNoise noise_;
};

}  // namespace btfracture
