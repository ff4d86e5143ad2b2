// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/MaterialField.h>

#include <cmath>

namespace btfracture {
namespace {

// Deterministic hash of a lattice point and the seed to [0, 1) (splitmix64 finaliser).
double latticeValue(std::int64_t i, std::int64_t j, std::int64_t k, std::uint64_t seed) {
    std::uint64_t h = seed ^ (static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull) ^
                      (static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4Full) ^
                      (static_cast<std::uint64_t>(k) * 0x165667B19E3779F9ull);
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 31;
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

// Value noise: smoothstep-interpolated lattice values, in [0, 1].
double valueNoise(const Eigen::Vector3d& p, std::uint64_t seed) {
    const Eigen::Vector3d f = p.array().floor();
    const Eigen::Vector3d t = p - f;
    const Eigen::Vector3d s = t.array() * t.array() * (3.0 - 2.0 * t.array());
    const std::int64_t i = static_cast<std::int64_t>(f.x()), j = static_cast<std::int64_t>(f.y()),
                       k = static_cast<std::int64_t>(f.z());
    double sum = 0.0;
    for (int c = 0; c < 8; ++c) {
        const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
        const double w = (dx ? s.x() : 1 - s.x()) * (dy ? s.y() : 1 - s.y()) * (dz ? s.z() : 1 - s.z());
        sum += w * latticeValue(i + dx, j + dy, k + dz, seed);
    }
    return sum;
}

}  // namespace

MaterialField::MaterialField(const Material& material, const MaterialNoise& noise)
    : material_(material), noise_(noise) {
    noise.validate("material field");
}

double MaterialField::variation(const Eigen::Vector3d& x) const {
    if (noise_.amplitude == 0.0) return 1.0;
    return 1.0 + noise_.amplitude * (2.0 * valueNoise(x / noise_.wavelength, noise_.seed) - 1.0);
}

double MaterialField::tensileStrength(const Eigen::Vector3d& x) const {
    return material_.tensileStrength() * variation(x);
}

double MaterialField::fractureToughness(const Eigen::Vector3d& x) const {
    return material_.fractureToughness() * variation(x);
}

}  // namespace btfracture
