// SPDX-License-Identifier: Zlib
#pragma once
// Quadric edge-collapse decimation (Garland & Heckbert 1997) for collision meshes.
#include <btFracture/core/TriangleMesh.h>

namespace btfracture {

// Collapses the edges of a closed, manifold, consistently oriented mesh in order of increasing
// quadric error (plus a small edge-length term that keeps flat regions well shaped) until at
// most targetTriangles remain. A collapse is skipped when it would break the manifold (link
// condition), leave fewer than 4 vertices, flip or nearly flip a triangle's normal (more than
// ~78 degrees) or create a degenerate triangle, so the result stays closed and manifold; when
// no allowed collapse is left the result has more triangles than asked (logged). A mesh that
// already has <= targetTriangles is returned unchanged. Edges that are not shared by exactly two
// triangles (holes, non-manifold edges) are never collapsed, so defects of the input are kept
// as they are, never made worse. Throws btfracture::Error naming mesh.name if
// targetTriangles < 4 or a triangle index is out of range.
TriangleMesh decimateMesh(const TriangleMesh& closedMesh, int targetTriangles);

}  // namespace btfracture
