// SPDX-License-Identifier: Zlib
#pragma once
// Removes triangles with an angle below a bound from a mesh that lives on a reference surface,
// by local edits that each raise the smallest angle of the region they touch: flipping an edge
// (a cap's long edge), collapsing an edge (a needle's short edge) and moving a vertex on the
// surface to where its triangles have the largest smallest angle. Topology never changes (link
// condition on every collapse), and no edit turns a triangle's normal by more than 60 degrees.
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/HalfEdgeMesh.h>

namespace btfracture {

struct QualityRepairResult {
    int edits = 0;           // flips, collapses and vertex moves made
    int passes = 0;          // sweeps over the bad triangles
    int trianglesBelow = 0;  // triangles still below the bound afterwards
};

// minAngle [rad]; edgeLength: the mesh's target edge length (limits how long a collapse may
// make an edge, 5/3 of it, and sets the vertex search step).
QualityRepairResult repairSmallAngles(HalfEdgeMesh& mesh, const ClosestPointTree& surface, double minAngle,
                                      double edgeLength, int maxPasses);

}  // namespace btfracture
