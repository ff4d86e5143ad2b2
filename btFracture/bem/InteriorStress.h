// SPDX-License-Identifier: Zlib
#pragma once
// Stress anywhere in the body from the boundary solution (paper §4.1, appendix Eq. 7): the
// Somigliana stress identity with the Kelvin kernels S1 (tractions) and S2 (displacements),
// handed over smoothly to the surface stress (Eq. 5) near the boundary, where the interior
// integral loses accuracy.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/SurfaceMesh.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

struct StressEvaluationSettings {
    // Hand-over band in units of the nearest triangle's diameter h: surface stress below
    // nearFraction * h, interior stress beyond farFraction * h, smoothstep blend between.
    double nearFraction = 0.25;
    double farFraction = 0.5;
    // Adaptive quadrature: a (sub)triangle closer than subdivisionRatio times its size to the
    // point is split in four, at most maxSubdivisions times; leaves use `ruleDegree` (16 points),
    // or fewer points farther away: `farDegree` (6) from farRatio sizes, `veryFarDegree` (3)
    // from veryFarRatio sizes (the kernels of Eq. 7 are smooth there; the rule's error falls as
    // (size / distance)^(degree + 1)).
    double subdivisionRatio = 2.0;
    int maxSubdivisions = 8;
    int ruleDegree = 6;
    double farRatio = 4.0;
    int farDegree = 4;
    double veryFarRatio = 8.0;
    int veryFarDegree = 2;
};

class StressEvaluator {
public:
    // Keeps references to mesh, displacements u (3n [m]) and tractions q (3m [Pa]).
    StressEvaluator(const SurfaceMesh& mesh, double youngsModulus, double poissonRatio,
                    const Eigen::VectorXd& displacements, const Eigen::VectorXd& tractions,
                    const StressEvaluationSettings& settings = {});

    // Includes traction-free cracks with the given openings (COD per crack node, 3 each, zero on
    // the front) in the interior stress: a crack acts as boundary with normal -n_c and
    // displacement COD (FORMULATION.md). Keeps references.
    void addCracks(const CrackMesh& cracks, const Eigen::VectorXd& nodalOpenings);

    // Blended stress at x [m, body frame]: interior Eq. 7 away from the surface, Eq. 5 on it.
    Eigen::Matrix3d stressAt(const Eigen::Vector3d& x) const;
    // Eq. 7 alone (diverges as x approaches the surface). x must be inside the body.
    Eigen::Matrix3d interiorStress(const Eigen::Vector3d& x) const;
    // Eq. 5 on the triangle nearest to x.
    Eigen::Matrix3d nearestSurfaceStress(const Eigen::Vector3d& x) const;

private:
    const SurfaceMesh& mesh_;
    double E_, nu_;
    const Eigen::VectorXd& u_;
    const Eigen::VectorXd& q_;
    StressEvaluationSettings settings_;
    std::vector<Eigen::Matrix3d> surface_;
    const CrackMesh* cracks_ = nullptr;
    const Eigen::VectorXd* openings_ = nullptr;
};

}  // namespace btfracture
