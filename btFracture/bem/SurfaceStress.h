// SPDX-License-Identifier: Zlib
#pragma once
// Surface stress per triangle, paper §4.1 and Eq. 5: the in-plane stress of the P1
// displacement (plane stress, "2D FEM"), made consistent with the known traction q and
// corrected for the Poisson contraction caused by the out-of-plane traction (nu / (1 - nu)).
#include <btFracture/bem/SurfaceMesh.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

// Stress [Pa] on `triangle` from nodal displacements u (3n, [m]) and its traction q [Pa].
// E [Pa], nu [-]. Symmetric, and sigma n = q exactly.
Eigen::Matrix3d surfaceStress(const SurfaceMesh& mesh, double youngsModulus, double poissonRatio,
                              int triangle, const Eigen::VectorXd& displacements,
                              const Eigen::Vector3d& traction);

// All triangles; tractions are P0, 3m values.
std::vector<Eigen::Matrix3d> surfaceStresses(const SurfaceMesh& mesh, double youngsModulus,
                                             double poissonRatio, const Eigen::VectorXd& displacements,
                                             const Eigen::VectorXd& tractions);

}  // namespace btfracture
