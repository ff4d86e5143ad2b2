// SPDX-License-Identifier: Zlib
#pragma once
// Self-intersection of a triangle mesh: pairs of triangles that meet anywhere other than in the
// vertices or the edge they share. Neighbours that only share a vertex or an edge do not count;
// two triangles on the same three vertices, or two triangles folded flat onto each other over a
// shared edge, do. Touching counts as intersecting (a solid must not touch itself).
//
// Candidate pairs come from an axis-aligned bounding-box tree over the triangles, so the cost is
// about O(n log n) for ordinary meshes (tens of milliseconds for 50k triangles). The predicates
// are floating point with a relative tolerance of 1e-12; they do not decide exactly-touching
// configurations at the rounding level.
#include <btFracture/core/TriangleMesh.h>

#include <utility>
#include <vector>

namespace btfracture {

// Intersecting pairs (i < j, sorted). Triangles with an invalid index, a non-finite corner or zero
// area are skipped (inspectMesh reports those separately).
std::vector<std::pair<int, int>> findSelfIntersections(const TriangleMesh& mesh);

}  // namespace btfracture
