// SPDX-License-Identifier: Zlib
#pragma once
// Shape quality of a triangle mesh, as the boundary element method sees it: angles (a triangle
// with all angles >= 20 degrees is neither a needle nor a sliver/cap) and edge lengths.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

struct MeshQuality {
    int triangleCount = 0;
    double minAngleDegrees = 0.0;      // smallest corner angle over all triangles
    double maxAngleDegrees = 0.0;      // largest corner angle over all triangles
    double meanMinAngleDegrees = 0.0;  // mean over triangles of each triangle's smallest angle
    double minEdgeLength = 0.0;        // [mesh units]
    double maxEdgeLength = 0.0;        // [mesh units]
    double meanEdgeLength = 0.0;       // [mesh units], over undirected edges
    double edgeLengthRatio = 0.0;      // maxEdgeLength / minEdgeLength
    double angleThresholdDegrees = 0.0;
    int trianglesBelowAngle = 0;  // triangles whose smallest angle is below the threshold
    int worstTriangle = -1;       // triangle with the smallest angle
};

// Throws btfracture::Error naming mesh.name for an empty mesh or an invalid vertex index.
MeshQuality measureQuality(const TriangleMesh& mesh, double angleThresholdDegrees = 20.0);

// The three interior angles [rad] at corners a, b, c (0 for a corner of a degenerate triangle).
Eigen::Vector3d triangleAngles(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);
// Smallest interior angle [rad].
double triangleMinAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace btfracture
