// SPDX-License-Identifier: Zlib
#pragma once
// Validation of triangle meshes that are meant to bound a solid.
#include <btFracture/core/TriangleMesh.h>

#include <string>

namespace btfracture {

struct MeshDefects {
    int invalidIndices = 0;       // triangle corners outside [0, vertex count)
    int nonFiniteVertices = 0;    // NaN or Inf coordinates
    int degenerateTriangles = 0;  // repeated corner or area below 1e-12 of the squared bbox diagonal
    int boundaryEdges = 0;        // edges used by one triangle (holes)
    int nonManifoldEdges = 0;     // edges used by more than two triangles
    int nonManifoldVertices = 0;  // vertices whose triangles form more than one fan
    int inconsistentEdges = 0;    // edges whose two triangles traverse it in the same direction
    int intersectingPairs = 0;    // pairs of triangles meeting beyond a shared vertex or edge
    int components = 0;           // edge-connected triangle components
    double signedVolume = 0.0;    // > 0 for outward-facing normals

    // True if the mesh is a closed, consistently oriented 2-manifold (may still self-intersect
    // or be inside-out).
    bool isClosedManifold() const;
    // isClosedManifold() and free of self-intersections: the mesh bounds a solid (orientation
    // may still be inside-out).
    bool isClosedSolid() const;
    // "3 boundary edges, 1 degenerate triangle" (empty when there is nothing to report).
    std::string describe() const;
};

// Every count above; the self-intersection test (core/SelfIntersection.h) runs over the valid,
// finite, non-zero-area triangles.
MeshDefects inspectMesh(const TriangleMesh& mesh);

// Throws btfracture::Error naming `mesh.name` and every defect count when the mesh is empty,
// open, non-manifold, inconsistently oriented, degenerate, non-finite or self-intersecting. A mesh
// that is merely inside-out is flipped in place with a warning. Returns the defect counts (all
// zero but `components` and `signedVolume`).
MeshDefects requireClosedSolid(TriangleMesh& mesh);

}  // namespace btfracture
