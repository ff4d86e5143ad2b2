#pragma once
// Target edge length over space for remeshing: a base length everywhere, shortened inside
// balls where the mesh needs more resolution (parts of the surface closer together than the
// base length, which a coarse mesh would make intersect). Lengths in mesh units.
#include <Eigen/Core>

#include <vector>

namespace btfracture {

class EdgeLengthField {
public:
    explicit EdgeLengthField(double baseLength) : base_(baseLength) {}

    double base() const { return base_; }
    void setBase(double baseLength) { base_ = baseLength; }

    // Target length at p: the base length times the smallest factor of the balls containing p.
    double at(const Eigen::Vector3d& p) const;
    // Multiplies the target length by `factor` (in (0, 1)) within `radius` of `centre`.
    void refine(const Eigen::Vector3d& centre, double radius, double factor);
    int refinements() const { return static_cast<int>(balls_.size()); }

private:
    struct Ball {
        Eigen::Vector3d centre;
        double radius2;
        double factor;
    };
    double base_;
    std::vector<Ball> balls_;
};

}  // namespace btfracture
