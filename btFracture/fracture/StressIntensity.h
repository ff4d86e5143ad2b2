// SPDX-License-Identifier: Zlib
#pragma once
// Stress intensity factors along crack fronts. FULL method (paper §3): displacement
// correlation (Ingraffea & Wawrzynek 2003) of the BEM crack opening at the node behind each
// front edge, in the front's local frame (paper Fig. 2b).
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
    int node = -1;             // crack node on the front
    Eigen::Vector3d position;  // [m], body frame
    FrontFrame frame;
    double KI = 0, KII = 0, KIII = 0;  // [Pa m^(1/2)]
    double spacing = 0;                // mean length of the adjacent front edges [m]
    // Driven by compression (EST's compressive eigenvector choice, or K_I < 0): the toughness
    // threshold is multiplied by the material's compressive factor.
    bool compressive = false;
};

// Per front node, averaged over its front edges. `nodalOpenings` holds COD = u+ - u- at every
// crack node (3 per node, zero on the front). Plane strain E' = E / (1 - nu^2):
//   K_I = E'/8 sqrt(2 pi / r) cod.n,  K_II = E'/8 sqrt(2 pi / r) cod.m,  K_III = mu/4 sqrt(2 pi / r) cod.t
// with r the distance of the correlation node from the front edge.
std::vector<FrontSifs> displacementCorrelation(const CrackMesh& cracks, const Eigen::VectorXd& nodalOpenings,
                                               const Material& material);

// Inverse of the correlation (used by the estimator's update, §4.3): the opening a front that
// has advanced by `distance` d leaves at its old position, cod = 2 K c sqrt(2 d) / (mu sqrt(pi))
// per mode with c = 1 - nu for modes I and II and c = 1 for mode III, in the given frame. The
// paper's formula has no factor 2: it gives the displacement of one crack face, while the
// opening (what the COD unknowns and displacementCorrelation use) is the jump between both.
// A compressive front (EST's K_I is a magnitude) closes: its normal jump is -|K_I| c ..., as the
// correlation's K_I < 0 would give (the BEM has no contact, FULL's faces interpenetrate too).
Eigen::Vector3d openingFromSifs(const FrontSifs& sifs, double distance, const Material& material);

}  // namespace btfracture
