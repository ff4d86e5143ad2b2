// SPDX-License-Identifier: Zlib
#pragma once
// Surface and crack triangles cut along crack mouths (FORMULATION.md, "Mouth"). The mouth line
// is the set of crack boundary edges that lie on the body's surface (CrackMesh::isMouthEdge). Each such edge
// is followed over the surface where its crack plane (else the normal section through it) cuts it, and every
// surface triangle it touches or crosses is split into pieces whose edges contain the line (a node inside a
// triangle splits it in three, a crossing point splits the two triangles of an edge). Every piece corner on
// the line carries the trace of the crack hats there (1 at a crack node, linear along a crack edge in
// between); a mouth node's cut surface hat is the P1 function of these values on the pieces on the side its
// crack normal points to (Γ₊, each sheet's sides its own where mouths cross), zero at every other corner.
// Crack triangles whose boundary edge passes through such points are split at them too, so that every pair of
// pieces that touches shares whole edges or corners (singular quadrature by ids).
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/PairIntegrals.h>
#include <btFracture/bem/SurfaceMesh.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace btfracture {

// Crack node -> value of its crack hat's trace at a point of the mouth line.
using MouthWeights = std::vector<std::pair<int, double>>;

struct MouthPiece {
    Panel panel;  // ids: surface node ids, surfaceNodeCount + crack node, or beyond for crossings
    std::array<MouthWeights, 3> weights;  // per corner; all empty on the - side of the mouth
};

struct MouthCut {
    // Surface triangle -> its pieces, for every surface triangle the mouth line splits or whose
    // cut hats are not zero (a triangle not split has one piece, itself).
    std::map<int, std::vector<MouthPiece>> surfacePieces;
    // Crack triangle -> its pieces, for crack triangles whose mouth edges pass through surface
    // edges or nodes (the pieces' weights then hold the crack hats of its three corners).
    std::map<int, std::vector<MouthPiece>> crackPieces;
    std::vector<std::pair<int, int>> unfollowedEdges;  // mouth edges left out of the cut (see cutAlongMouths)
};

// Surface ids of crack nodes: the surface node a crack node lies on, else nodeCount + crack node.
int mouthIdOf(const SurfaceMesh& mesh, const CrackMesh& cracks, int crackNode);

// A mouth edge that cannot be followed over the surface (its crack plane does not lead from one
// node to the other near the chord) is left out of the cut, counted and logged (debug).
MouthCut cutAlongMouths(const SurfaceMesh& mesh, const CrackMesh& cracks);

}  // namespace btfracture
