// SPDX-License-Identifier: Zlib
#pragma once
// Stress intensity factors along crack fronts. FULL method (paper §3): displacement
// correlation (Ingraffea & Wawrzynek 2003) of the BEM crack opening, fitted over the crack nodes
// a few rows behind each front node, in the front's local frame (paper Fig. 2b).
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/core/Material.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

// Local frame at a front point: m points ahead of the crack (direction of propagation), n is
// the crack normal n_c, t = m x n runs along the front (paper Fig. 2b).
struct FrontFrame {
    Eigen::Vector3d ahead, normal, tangent;
};

struct FrontSifs {
    int node = -1;                                       // crack node on the front
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m], body frame
    FrontFrame frame;
    double KI = 0, KII = 0, KIII = 0;  // [Pa m^(1/2)]
    double spacing = 0;                // mean length of the adjacent front edges [m]
    // Driven by compression (EST's compressive eigenvector choice, or K_I < 0): the toughness
    // threshold is multiplied by the material's compressive factor.
    bool compressive = false;
};

// Per front node: frame and spacing h averaged over its front edges, SIFs from a weighted least-
// squares fit of the opening at the crack nodes between 1.5 h and 4.5 h from the front (nearest
// front edge), within 2.5 h along it (hat weight), to the near-front profile of a front with
// in-plane curvature kappa (the penny's exact profile):
//   cod.n = 8/E' K_I g,  cod.m = 8/E' K_II g,  cod.t = 4/mu K_III g,  g = sqrt(r/2pi (1 - kappa r/2))
// with E' = E / (1 - nu^2). The nodes nearest the front are left out: there the P1 opening of
// the Galerkin solution is off the sqrt profile by a fixed fraction at any refinement (measured
// on the penny: +5 % in the first row, -1 % in the second, < 0.5 % beyond), so correlating them
// does not converge. The window ends within the square-root zone: at most a quarter of the
// sheet's extent behind the node and, on a convex front, 0.75 / kappa. Where that leaves less
// than 2.5 h (a crack resolved by fewer than about ten elements across), or no node, the node
// correlates its first row: per front edge the opening at the node opposite it, at distance r,
// with g = sqrt(r / 2pi), averaged over the node's edges.
// `nodalOpenings` holds COD = u+ - u- at every crack node (3 per node, zero on the front); all
// zero gives the frames alone (SIFs zero).
std::vector<FrontSifs> displacementCorrelation(const CrackMesh& cracks, const Eigen::VectorXd& nodalOpenings,
                                               const Material& material);

// Inverse of the correlation for a straight front (used by the estimator's update, §4.3): the
// opening a front that has advanced by `distance` d leaves at its old position, cod = 2 K c sqrt(2 d) / (mu
// sqrt(pi)) per mode with c = 1 - nu for modes I and II and c = 1 for mode III, in the given frame. The
// paper's formula has no factor 2: it gives the displacement of one crack face, while the
// opening (what the COD unknowns and displacementCorrelation use) is the jump between both.
// A compressive front (EST's K_I is a magnitude) closes: its normal jump is -|K_I| c ..., as the
// correlation's K_I < 0 would give (the BEM has no contact, FULL's faces interpenetrate too).
Eigen::Vector3d openingFromSifs(const FrontSifs& sifs, double distance, const Material& material);

}  // namespace btfracture
