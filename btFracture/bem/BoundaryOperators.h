// SPDX-License-Identifier: Zlib
#pragma once
// Symmetric Galerkin operators of 3D linear elastostatics on a closed SurfaceMesh, with P1
// displacements and P0 tractions (formulas in FORMULATION.md):
//   K = hypersingular operator D, the paper's "surface stiffness" (appendix Eq. 8)
//   F = (1/2 M - K') mapping P0 tractions q to the right-hand side f = F q (appendix Eq. 9)
// so that the pure Neumann problem reads K u = F q.
#include <btFracture/bem/PairIntegrals.h>
#include <btFracture/bem/SurfaceMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct ElasticConstants {
    double shearModulus;  // mu [Pa]
    double poissonRatio;  // nu [-]
};

struct BoundaryOperators {
    // 3n x 3n, node-major unknowns (3 p + i); symmetric positive semi-definite with the six
    // rigid motions in its null space. Units: Pa m^2 (force per displacement times area).
    Eigen::MatrixXd stiffness;
    // 3n x 3m, traction unknowns triangle-major (3 t + j). Units: m^2.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> tractionToLoad;
};

Panel panelOf(const SurfaceMesh& mesh, int triangle);
// Every triangle of the mesh as a QuadraturePanel, in triangle order.
std::vector<QuadraturePanel> quadraturePanels(const SurfaceMesh& mesh, const QuadratureSettings& quadrature);

// Assembles K and F in parallel (OpenMP). Deterministic: the result is bit-identical for any
// thread count (triangles are coloured so that concurrent writers never share a node, and each
// entry is summed in a fixed order).
BoundaryOperators assembleBoundaryOperators(const SurfaceMesh& mesh, const ElasticConstants& material,
                                            const QuadratureSettings& quadrature = {});

// Greedy colouring: triangles of one colour share no node. Returns one list per colour.
std::vector<std::vector<int>> colourTrianglesByNodes(const SurfaceMesh& mesh);

}  // namespace btfracture
