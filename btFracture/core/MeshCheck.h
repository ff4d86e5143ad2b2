#pragma once
// Validation of triangle meshes that are meant to bound a solid.
#include <btFracture/core/TriangleMesh.h>

#include <string>

namespace btfracture {

struct MeshDefects {
    int invalidIndices = 0;        // triangle corners outside [0, vertex count)
    int nonFiniteVertices = 0;     // NaN or Inf coordinates
    int degenerateTriangles = 0;   // repeated corner or area below 1e-12 of the squared bbox diagonal
    int boundaryEdges = 0;         // edges used by one triangle (holes)
    int nonManifoldEdges = 0;      // edges used by more than two triangles
    int nonManifoldVertices = 0;   // vertices whose triangles form more than one fan
    int inconsistentEdges = 0;     // edges whose two triangles traverse it in the same direction
    int components = 0;            // edge-connected triangle components
    double signedVolume = 0.0;     // > 0 for outward-facing normals

    // True if the mesh can bound a solid (orientation may still be inside-out).
    bool isClosedManifold() const;
    // "3 boundary edges, 1 degenerate triangle" (empty when there is nothing to report).
    std::string describe() const;
};

MeshDefects inspectMesh(const TriangleMesh& mesh);

// Throws btfracture::Error naming `mesh.name` and every defect count when the mesh is empty,
// open, non-manifold, inconsistently oriented, degenerate or non-finite. A mesh that is merely
// inside-out is flipped in place with a warning.
void requireClosedSolid(TriangleMesh& mesh);

}  // namespace btfracture
