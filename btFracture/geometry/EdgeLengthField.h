// SPDX-License-Identifier: Zlib
#pragma once
// Target edge length over space for remeshing: a base length everywhere, shortened near sizing
// sites (thin, curved parts of the surface that need smaller elements than the base length to
// stay apart, ThicknessSizing.h) and inside balls where the mesh needs more resolution (parts
// of the surface closer together than the base length, which a coarse mesh would make
// intersect). Lengths in mesh units.
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace btfracture {

// A place on the surface that asks for edges of at most `length` there, when the base length
// is `referenceBase`.
struct SizingSite {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double length = 0.0;
};

class EdgeLengthField {
public:
    explicit EdgeLengthField(double baseLength) : base_(baseLength) {}

    double base() const { return base_; }
    // Sets the base length; site lengths scale with it.
    void setBase(double baseLength) { base_ = baseLength; }

    // Target length at p: the smaller of the base length times the smallest factor of the balls
    // containing p and s G(p), s = base / referenceBase (sites follow the base both ways) or
    // min(1, base / referenceBase) (a longer base leaves the sites' lengths as they are), G(p) = min over the
    // sites i of length_i + grading |p - centre_i| (a length that grows by `grading` per unit distance away
    // from a site, so that triangles can grade from small to large with good angles). G is evaluated at the
    // nodes of a lattice of spacing half the smallest site length (once per node, when first needed) and
    // interpolated trilinearly between them.
    double at(const Eigen::Vector3d& p) const;
    // Replaces the sizing sites; `referenceBase` is the base their lengths refer to. grading > 0.
    void setSites(const std::vector<SizingSite>& sites, double referenceBase, double grading,
                  bool followLongerBase);
    int siteCount() const { return static_cast<int>(sites_.size()); }
    // Multiplies the target length by `factor` (in (0, 1)) within `radius` of `centre`.
    void refine(const Eigen::Vector3d& centre, double radius, double factor);
    int refinements() const { return static_cast<int>(balls_.size()); }

private:
    double siteTerm(const Eigen::Vector3d& p) const;  // G at a point, from the sites
    double latticeValue(const Eigen::Vector3i& node) const;
    struct Ball {
        Eigen::Vector3d centre;
        double radius2;
        double factor;
    };
    double base_;
    std::vector<Ball> balls_;
    // Sites bucketed in a regular grid of cells of size cell_ from origin_ (cellStart_: first
    // site of each cell in sites_, one past the end at the back).
    std::vector<SizingSite> sites_;
    std::vector<int> cellStart_;
    Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
    Eigen::Vector3i cells_ = Eigen::Vector3i::Zero();
    bool followLongerBase_ = true;
    double cell_ = 1.0, referenceBase_ = 1.0, grading_ = 1.0, smallestSite_ = 0.0, spacing_ = 1.0;
    mutable std::unordered_map<std::int64_t, double> lattice_;  // G at the nodes evaluated so far
};

}  // namespace btfracture
