// SPDX-License-Identifier: Zlib
#pragma once
// Mean curvature at a contact point, the inverse of the Hertz radius (paper §5.1).
//
// Meshes (btFractureRigidBody): discrete mean curvature per vertex from the Steiner formula,
//   H_v = sum over edges e at v of theta_e |e| / (4 A_v),  A_v = one third of the adjacent area,
// with theta_e the signed dihedral angle (convex > 0), then interpolated barycentrically at the
// closest surface point. On coarse meshes of boxy bodies this is a proxy (a 12-triangle cube
// reads as a sphere of about 0.6 edge lengths); the Hertz radius is capped at the body size
// anyway (HertzContact.h). Concave (negative) values count as flat there.
// Bullet primitives (plain btRigidBody partners): sphere 1/r; capsule 1/r on the caps and
// 1/(2r) on the side; cylinder 1/(2r) on the side and 0 on the end caps; every other shape (box,
// plane, hull, mesh, compound) is treated as flat (0).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

class btCollisionShape;

namespace btfracture {

// Per-vertex mean curvature [1/m] of a closed mesh; vertices without triangles get 0.
std::vector<double> vertexMeanCurvature(const TriangleMesh& mesh);

// Mean curvature [1/m] at the surface point closest to `point` (mesh frame).
double meanCurvatureAt(const TriangleMesh& mesh, const std::vector<double>& vertexCurvature,
                       const Eigen::Vector3d& point);

// Mean curvature [1/m] of a Bullet shape at `localPoint` (shape frame), as described above.
double shapeMeanCurvature(const btCollisionShape& shape, const Eigen::Vector3d& localPoint);

}  // namespace btfracture
