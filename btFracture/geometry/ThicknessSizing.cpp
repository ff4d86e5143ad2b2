// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ThicknessSizing.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

namespace btfracture {
namespace {

constexpr double kSamplesPerBase = 3.0;      // sample spacing L / 3
constexpr std::size_t kMaxSamples = 400000;  // the spacing grows beyond this
constexpr double kThinBelow = 1.0;           // samples with T >= L ask for nothing
constexpr double kSiteBelow = 0.9;           // sites only where h < 0.9 L
constexpr double kMinAngle = 10.0 * M_PI / 180.0;
constexpr double kMaxAngle = 120.0 * M_PI / 180.0;

struct Sample {
    Eigen::Vector3d point, normal;
};

// Centroids of the k x k sub-triangles of every triangle, k = ceil(longest edge / spacing).
std::vector<Sample> sampleSurface(const ClosestPointTree& surface, double spacing) {
    const TriangleMesh& mesh = surface.mesh();
    auto subdivisions = [&](int t, double h) {
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]],
                              &c = mesh.vertices[tri[2]];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        return std::max(1, static_cast<int>(std::ceil(longest / h)));
    };
    std::size_t total = 0;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        const std::size_t k = subdivisions(t, spacing);
        total += k * k;
    }
    if (total > kMaxSamples) spacing *= std::sqrt(static_cast<double>(total) / kMaxSamples);
    std::vector<Sample> samples;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        const Eigen::Vector3d& n = surface.triangleNormal(t);
        if (n.isZero()) continue;
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector3d &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]],
                              &c = mesh.vertices[tri[2]];
        const int k = subdivisions(t, spacing);
        auto add = [&](double u, double v) { samples.push_back({a + u / k * (b - a) + v / k * (c - a), n}); };
        for (int i = 0; i < k; ++i)
            for (int j = 0; i + j < k; ++j) {
                add(i + 1.0 / 3.0, j + 1.0 / 3.0);
                if (i + j + 1 < k) add(i + 2.0 / 3.0, j + 2.0 / 3.0);
            }
    }
    return samples;
}

// Samples bucketed by the cell of size `cell` that holds them.
class SampleGrid {
public:
    SampleGrid(const std::vector<Sample>& samples, double cell) : cell_(cell) {
        for (int i = 0; i < static_cast<int>(samples.size()); ++i)
            keyed_.emplace_back(key(cellOf(samples[i].point)), i);
        std::sort(keyed_.begin(), keyed_.end());
    }
    // Calls f(cellSamples, nearSamples) for every occupied cell: its samples and those of the
    // 27 cells around it (itself included), in a fixed order.
    template <class F>
    void forEachCell(F&& f) const {
        std::vector<int> own, near;
        for (std::size_t first = 0; first < keyed_.size();) {
            std::size_t last = first;
            own.clear();
            while (last < keyed_.size() && keyed_[last].first == keyed_[first].first)
                own.push_back(keyed_[last++].second);
            const Eigen::Vector3i c = cellOfKey(keyed_[first].first);
            near.clear();
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const std::int64_t k = key(c + Eigen::Vector3i(dx, dy, dz));
                        auto it = std::lower_bound(keyed_.begin(), keyed_.end(), std::make_pair(k, -1));
                        for (; it != keyed_.end() && it->first == k; ++it) near.push_back(it->second);
                    }
            f(own, near);
            first = last;
        }
    }

private:
    static constexpr std::int64_t kSpan = std::int64_t(1) << 21;  // cells per axis
    Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const { return (p / cell_).array().floor().cast<int>(); }
    static std::int64_t key(const Eigen::Vector3i& c) {
        return ((c.z() + kSpan / 2) * kSpan + (c.y() + kSpan / 2)) * kSpan + (c.x() + kSpan / 2);
    }
    static Eigen::Vector3i cellOfKey(std::int64_t k) {
        const int x = static_cast<int>(k % kSpan) - kSpan / 2;
        k /= kSpan;
        const int y = static_cast<int>(k % kSpan) - kSpan / 2;
        const int z = static_cast<int>(k / kSpan) - kSpan / 2;
        return Eigen::Vector3i(x, y, z);
    }
    double cell_;
    std::vector<std::pair<std::int64_t, int>> keyed_;
};

}  // namespace

std::vector<SizingSite> thicknessSizingSites(const ClosestPointTree& surface, double baseLength,
                                             const ThicknessSizingOptions& options) {
    const double L = baseLength;
    const std::vector<Sample> samples = sampleSurface(surface, L / kSamplesPerBase);
    const SampleGrid grid(samples, L);
    const double floor = options.smallestFactor * L;
    // 2 sin(theta / 2) = |n - m| for unit normals n, m at an angle theta.
    const double minChord = 2.0 * std::sin(0.5 * kMinAngle), maxChord = 2.0 * std::sin(0.5 * kMaxAngle);
    // Smallest length asked for per site cell (L / 4), in a deterministic order.
    std::map<std::tuple<int, int, int>, SizingSite> cells;
    grid.forEachCell([&](const std::vector<int>& own, const std::vector<int>& near) {
        for (const int i : own) {
            const Sample& s = samples[i];
            const ClosestPointTree::Hit across =
                surface.closestPointWithin(s.point, -s.normal, 0.5, kThinBelow * L);
            // Only across the material: a gap between two parts is not a wall to keep.
            if (across.triangle < 0 || (across.point - s.point).dot(s.normal) >= 0.0) continue;
            const double thickness = std::sqrt(across.squaredDistance);
            // h < kSiteBelow L needs R below this.
            const double wanted = std::pow(kSiteBelow * L, 2) / (8.0 * options.sagFraction * thickness);
            double radius = wanted;
            for (const int j : near) {
                const double chord2 = (samples[j].normal - s.normal).squaredNorm();
                if (chord2 <= minChord * minChord || chord2 >= maxChord * maxChord) continue;
                const double chord = std::sqrt(chord2);
                if (0.5 * L >= radius * chord) continue;
                const double d2 = (samples[j].point - s.point).squaredNorm();
                if (d2 < 0.25 * L * L || d2 > L * L) continue;
                radius = std::min(radius, std::sqrt(d2) / chord);
            }
            if (radius >= wanted) continue;
            const double length = std::max(floor, std::sqrt(8.0 * options.sagFraction * thickness * radius));
            const Eigen::Vector3i c = (s.point / (0.25 * L)).array().floor().cast<int>();
            auto [it, fresh] = cells.try_emplace({c.x(), c.y(), c.z()}, SizingSite{s.point, length});
            if (!fresh && length < it->second.length) it->second = SizingSite{s.point, length};
        }
    });
    std::vector<SizingSite> sites;
    sites.reserve(cells.size());
    for (const auto& [cell, site] : cells) sites.push_back(site);
    return sites;
}

}  // namespace btfracture
