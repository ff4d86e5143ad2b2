// SPDX-License-Identifier: Zlib
#pragma once
// A closed mesh moved inward by a distance d, so that the surface Bullet collides with (a GImpact
// mesh's triangles inflated by its collision margin d) lies on the input instead of d outside it.
// Vertex v moves by the delta that minimises sum_f A_f (n_f . delta + d)^2 over its triangles f
// (areas A_f, unit outward normals n_f), the smallest such delta where the planes leave a
// direction free (pseudo-inverse): every plane through v moves in by d, a vertex on a flat region
// moves by d along its inward normal and a corner of a box along its diagonal by d sqrt(3).
// |delta| stays at most 3 d. Where the wall behind v is thinner than about 2 d the move is halved
// (up to 4 times, then v stays) until the moved vertex is inside and at least 0.8 of its move's
// depth away from every part of the input, so thin parts are never turned inside out; a spike
// that this stops tries its inward normal.
#include <btFracture/core/TriangleMesh.h>

namespace btfracture {

struct MeshInset {
    TriangleMesh mesh;              // same topology as the input
    double smallestFraction = 1.0;  // least fraction of d that any vertex moved in
    int reducedVertices = 0;        // vertices that moved less than d (thin walls)
};

// Throws btfracture::Error naming closedMesh.name if distance is negative or not finite, or (for
// distance > 0) a triangle index is out of range. distance 0 returns the mesh unchanged.
// Deterministic.
MeshInset insetMesh(const TriangleMesh& closedMesh, double distance);

}  // namespace btfracture
