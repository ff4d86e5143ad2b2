// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/EdgeLengthField.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {
constexpr int kMaxCellsPerAxis = 64;
}

double EdgeLengthField::at(const Eigen::Vector3d& p) const {
    double factor = 1.0;
    for (const Ball& ball : balls_)
        if ((p - ball.centre).squaredNorm() <= ball.radius2) factor = std::min(factor, ball.factor);
    const double length = base_ * factor;
    if (sites_.empty()) return length;
    const Eigen::Vector3d x = p / spacing_;
    const Eigen::Vector3d floor = x.array().floor();
    const Eigen::Vector3i node = floor.cast<int>();
    const Eigen::Vector3d w = x - floor;
    double g = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        double weight = 1.0;
        Eigen::Vector3i n = node;
        for (int k = 0; k < 3; ++k) {
            const bool upper = (corner >> k) & 1;
            n[k] += upper;
            weight *= upper ? w[k] : 1.0 - w[k];
        }
        g += weight * latticeValue(n);
    }
    const double scale = base_ / referenceBase_;
    return std::min(length, (followLongerBase_ ? scale : std::min(1.0, scale)) * g);
}

double EdgeLengthField::latticeValue(const Eigen::Vector3i& node) const {
    constexpr std::int64_t span = std::int64_t(1) << 21;
    const std::int64_t key =
        ((node.z() + span / 2) * span + (node.y() + span / 2)) * span + (node.x() + span / 2);
    const auto [it, fresh] = lattice_.try_emplace(key, 0.0);
    if (fresh) it->second = siteTerm(node.cast<double>() * spacing_);
    return it->second;
}

double EdgeLengthField::siteTerm(const Eigen::Vector3d& p) const {
    // Sites farther than this cannot give less than the cap: twice the reference base, more
    // than any base a triangle budget steers to.
    const double cap = 2.0 * referenceBase_;
    const double reach = (cap - smallestSite_) / grading_;
    double length = cap;
    Eigen::Vector3i lo, hi;
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::max(0, static_cast<int>(std::floor((p[k] - reach - origin_[k]) / cell_)));
        hi[k] = std::min(cells_[k] - 1, static_cast<int>(std::floor((p[k] + reach - origin_[k]) / cell_)));
        if (lo[k] > hi[k]) return length;
    }
    for (int z = lo.z(); z <= hi.z(); ++z)
        for (int y = lo.y(); y <= hi.y(); ++y)
            for (int x = lo.x(); x <= hi.x(); ++x) {
                const int c = (z * cells_.y() + y) * cells_.x() + x;
                for (int i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
                    length = std::min(length, sites_[i].length + grading_ * (p - sites_[i].centre).norm());
            }
    return length;
}

void EdgeLengthField::setSites(const std::vector<SizingSite>& sites, double referenceBase, double grading,
                               bool followLongerBase) {
    followLongerBase_ = followLongerBase;
    sites_.clear();
    cellStart_.clear();
    lattice_.clear();
    referenceBase_ = referenceBase;
    grading_ = grading;
    if (sites.empty()) return;
    Eigen::AlignedBox3d box;
    smallestSite_ = sites.front().length;
    for (const SizingSite& s : sites) {
        box.extend(s.centre);
        smallestSite_ = std::min(smallestSite_, s.length);
    }
    spacing_ = 0.5 * smallestSite_;
    cell_ = std::max(referenceBase, box.sizes().maxCoeff() / kMaxCellsPerAxis);
    origin_ = box.min();
    for (int k = 0; k < 3; ++k) cells_[k] = static_cast<int>(std::floor(box.sizes()[k] / cell_)) + 1;
    auto cellOf = [&](const Eigen::Vector3d& p) {
        Eigen::Vector3i c;
        for (int k = 0; k < 3; ++k)
            c[k] = std::clamp(static_cast<int>(std::floor((p[k] - origin_[k]) / cell_)), 0, cells_[k] - 1);
        return (c.z() * cells_.y() + c.y()) * cells_.x() + c.x();
    };
    // Counting sort by cell (stable: the sites keep their order within a cell).
    cellStart_.assign(static_cast<std::size_t>(cells_.prod()) + 1, 0);
    for (const SizingSite& s : sites) ++cellStart_[cellOf(s.centre) + 1];
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
    sites_.resize(sites.size());
    for (const SizingSite& s : sites) sites_[fill[cellOf(s.centre)]++] = s;
}

void EdgeLengthField::refine(const Eigen::Vector3d& centre, double radius, double factor) {
    balls_.push_back({centre, radius * radius, at(centre) / base_ * factor});
}

}  // namespace btfracture
