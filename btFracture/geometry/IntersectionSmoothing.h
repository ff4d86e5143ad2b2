// SPDX-License-Identifier: Zlib
#pragma once
// A coarse mesh of a surface that does not touch itself can still intersect itself: chords
// between vertices on two close parts (the armadillo's claws, an ear against the head) cut
// across the narrow gap between them. Smoothing the vertices of the intersecting triangles
// (towards the centroid of their neighbours, off the surface) straightens those chords apart.
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/HalfEdgeMesh.h>

namespace btfracture {

struct IntersectionSmoothingResult {
    int rounds = 0;          // find-and-smooth rounds run
    int moves = 0;           // vertex moves made
    int edits = 0;           // edge flips and collapses made
    int remainingPairs = 0;  // intersecting triangle pairs left (core/SelfIntersection.h)
};

// Each round finds the intersecting triangle pairs and moves every vertex of those triangles
// half (else a quarter of) the way to the centroid of its neighbours, unless that would take an
// angle around it below min(minAngle, what it was) [rad] or turn a triangle by more than 60
// degrees. After a round without progress, the flip or collapse of an edge of those triangles
// that most reduces the pairs (same angle rule, edges up to 2 edgeLength) is made if there is
// one, else the next rounds also smooth the neighbours (up to two rings). Compacts the mesh.
IntersectionSmoothingResult smoothSelfIntersections(HalfEdgeMesh& mesh, const ClosestPointTree& surface,
                                                    double minAngle, double edgeLength, int maxRounds);

}  // namespace btfracture
