#pragma once
// Exact mass properties of the solid bounded by a closed triangle mesh (polyhedral integrals
// over the signed tetrahedra spanned by each triangle and a reference point).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct MassProperties {
    double volume = 0.0;                                     // V [m^3]
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();  // c [m], mesh frame
    // Unit-density inertia tensor about the centre of mass, mesh-frame axes [m^5]:
    // J = integral of (|r|^2 I - r r^T) dV with r = x - c. Multiply by the density for kg m^2.
    Eigen::Matrix3d inertiaAboutCom = Eigen::Matrix3d::Zero();
};

// The mesh must be closed and outward-oriented (see requireClosedSolid); this function does not
// check that. Throws btfracture::Error naming mesh.name when the enclosed volume is not
// positive and finite (empty, open or inside-out input).
MassProperties computeMassProperties(const TriangleMesh& mesh);

// Principal frame of an inertia tensor: inertia = rotation * diag(moments) * rotation^T with
// moments ascending, rotation a proper rotation (det +1) and a deterministic sign convention
// (the largest-magnitude component of each column is positive for the first two columns).
struct PrincipalAxes {
    Eigen::Vector3d moments;
    Eigen::Matrix3d rotation;
};
PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia);

}  // namespace btfracture
