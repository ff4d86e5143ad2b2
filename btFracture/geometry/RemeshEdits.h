// SPDX-License-Identifier: Zlib
#pragma once
// Local edits of a HalfEdgeMesh whose vertices live on a reference surface (a ClosestPointTree):
// projection, the best place for an edge collapse, and moving one vertex to where its triangles
// have the largest smallest angle. Shared by isotropic remeshing (Remesh.h) and the quality
// repair (QualityRepair.h). Angles in radians, lengths in mesh units.
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/HalfEdgeMesh.h>

#include <Eigen/Core>

namespace btfracture {

// Closest point of the surface to p among triangles facing the same way as `normal` (within
// 90 degrees), so that points near a thin part stay on their own side.
Eigen::Vector3d projectOntoSurface(const ClosestPointTree& surface, const Eigen::Vector3d& p,
                                   const Eigen::Vector3d& normal);

// Midpoint of the edge of h projected onto the surface (facing like the two faces at h).
Eigen::Vector3d edgeMidpointOnSurface(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int h);

// Largest valence a collapse may give the merged vertex (regular meshes have 6).
constexpr int kMaxCollapsedValence = 12;

struct CollapseLimits {
    double maxEdgeLength;    // no edge at the merged vertex may be this long or longer
    double minNormalCosine;  // every surviving face keeps its normal within acos(this)
    double maxDeviation;     // the removed vertex positions stay this close to the new faces
};

// What makes one place for a collapse better than another.
enum class CollapseGoal {
    KeepShape,     // least deviation from the current surface (keeps tips and ridges)
    LargestAngle,  // largest smallest angle of the new faces
};

struct CollapsePlan {
    bool valid = false;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // where the merged vertex goes
    double minAngle = 0.0;                               // smallest angle of the faces around it
    double deviation = 0.0;                              // HalfEdgeMesh::EditPreview::deviation
};

// Best of three places for collapsing the edge of h (its midpoint projected onto the surface,
// or either end); invalid when the collapse would break the manifold (link condition) or no
// place meets the limits.
CollapsePlan planCollapse(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int h,
                          const CollapseLimits& limits, CollapseGoal goal);

// How far the surface moves when vertex v moves to q: the distance from v's current position to
// the faces around q.
double moveDeviation(const HalfEdgeMesh& mesh, int v, const Eigen::Vector3d& q);

struct VertexMove {
    bool improved = false;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    double minAngle = 0.0;  // smallest angle around the vertex at `position`
};

// Pattern search in the tangent plane of v (each trial point projected onto the surface) for
// the position that maximizes the smallest angle of the faces around v without turning any of
// them by more than acos(minNormalCosine). `step` is the first search step.
VertexMove optimizeVertexAngles(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int v, double step,
                                double minNormalCosine);

}  // namespace btfracture
