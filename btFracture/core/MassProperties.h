#pragma once
// Exact mass properties of a closed, outward-oriented triangle mesh (divergence theorem over
// the tetrahedra spanned by each triangle and the origin).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct MassProperties {
    double volume = 0.0;                                   // [m^3]
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();  // [m], mesh frame
    // Inertia tensor about the centre of mass for density 1 [m^5]; multiply by density [kg/m^3].
    Eigen::Matrix3d inertiaPerDensity = Eigen::Matrix3d::Zero();
};

// Throws btfracture::Error naming mesh.name if the enclosed volume is not positive.
MassProperties computeMassProperties(const TriangleMesh& mesh);

}  // namespace btfracture
