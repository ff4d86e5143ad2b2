// SPDX-License-Identifier: Zlib
#pragma once
// Exact mass properties of a closed, outward-oriented triangle mesh (divergence theorem over
// the tetrahedra spanned by each triangle and the origin).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct MassProperties {
    double volume = 0.0;                                     // [m^3]
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();  // [m], mesh frame
    // Inertia tensor about the centre of mass for density 1 [m^5]; multiply by density [kg/m^3].
    Eigen::Matrix3d inertiaPerDensity = Eigen::Matrix3d::Zero();
};

// Throws btfracture::Error naming mesh.name if the enclosed volume is not positive.
MassProperties computeMassProperties(const TriangleMesh& mesh);

// Signed volume enclosed by the mesh [m^3] (positive for a closed outward mesh), summed over the
// tetrahedra from `about` to each triangle: the same for any point if the mesh is closed, not if
// it has holes. Never throws.
double enclosedVolume(const TriangleMesh& mesh, const Eigen::Vector3d& about = Eigen::Vector3d::Zero());

// Sum of the triangle areas [m^2].
double surfaceArea(const TriangleMesh& mesh);

// Principal frame of a symmetric inertia tensor: inertia = rotation * diag(moments) * rotation^T
// with moments ascending and rotation proper (det +1). Deterministic signs: the largest-magnitude
// component of each of the first two columns is positive, the third is their cross product.
// Throws btfracture::Error when the tensor is not finite.
struct PrincipalAxes {
    Eigen::Vector3d moments = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};
PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia);

}  // namespace btfracture
