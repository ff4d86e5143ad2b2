// SPDX-License-Identifier: Zlib
#pragma once
// The regulariser T = (T_d; T_r) of paper Eq. 1-2 (6 x 3n): mean surface displacement and mean
// surface rotation of a P1 displacement field, and the P0 net force / torque of tractions.
#include <btFracture/bem/SurfaceMesh.h>

#include <Eigen/Core>

namespace btfracture {

// Rows 0-2: T_d u = int u dx (Eq. 1); rows 3-5: T_r u = int u x x dx (Eq. 2). Units: m^2, m^3.
Eigen::MatrixXd rigidModeOperator(const SurfaceMesh& mesh);

// 6 x 3m: net force int q dx (rows 0-2) and net torque int x x q dx (rows 3-5) of P0 tractions
// (the constraint matrix A of Eq. 6).
Eigen::MatrixXd netLoadOperator(const SurfaceMesh& mesh);

// The six rigid motions as P1 fields (3n x 6): translations e_x, e_y, e_z, then rotations
// w x x about the origin for w = e_x, e_y, e_z.
Eigen::MatrixXd rigidMotions(const SurfaceMesh& mesh);

}  // namespace btfracture
