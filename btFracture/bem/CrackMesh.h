// SPDX-License-Identifier: Zlib
#pragma once
// All crack sheets of one body (paper §3): single sheets of flat triangles inside the body,
// oriented so that each triangle's normal is the crack normal n_c. The unknown on a node is
// the crack opening displacement COD = u+ - u- (+ on the side n_c points to). It is zero on
// front nodes (the sheet's boundary inside the body). A sheet that reaches the body's surface
// opens there: its boundary nodes on the surface (on a surface node, edge or triangle) are mouth
// nodes and carry unknowns like interior nodes, except where the front meets the surface (a node
// on the surface next to a front node inside); see FORMULATION.md, "Cracks". Boundary nodes
// anywhere else (outside the body) are front, and nodes held shut (holdShut: carried sheets'
// nodes outside the fragment) carry no opening either. Sheets only grow by triangles
// attached at their boundary, so an unknown node's support never changes and the crack blocks
// can be extended incrementally.
#include <btFracture/bem/PairIntegrals.h>
#include <btFracture/bem/SurfaceMesh.h>

#include <Eigen/Core>

#include <array>
#include <set>
#include <utility>
#include <vector>

namespace btfracture {

class CrackMesh {
public:
    int addNode(const Eigen::Vector3d& position);  // body frame [m]; returns the node index
    int addTriangle(int a, int b, int c);          // counter-clockwise around n_c
    // Recomputes the front, numbers the unknowns of nodes that became interior or mouth since
    // the last call (existing unknowns keep their numbers) and returns those nodes. Throws if a
    // sheet is not an edge-manifold open surface. Only nodes matched to a body's surface by an
    // earlier call with that body can be mouth nodes.
    std::vector<int> refreshUnknowns();
    // The same after matching the nodes not matched yet (nodes never move) to the surface node,
    // the inside of the surface edge or the inside of the surface triangle of `body` they lie on
    // (within 1e-9 of its radius).
    std::vector<int> refreshUnknowns(const SurfaceMesh& body);
    // Makes the sheet edges a-b front from now on (no mouth edges: their mouth could not be cut,
    // MouthCut), withdraws the unknowns numbered from `kept` on and renumbers (nodes with earlier
    // unknowns keep them). Returns the nodes numbered anew.
    std::vector<int> holdAsFront(const std::vector<std::pair<int, int>>& edges, int kept);
    // Keeps the given nodes at zero opening from now on, interior ones too (carried sheets' nodes
    // outside the fragment that carries them); they must not carry an unknown yet.
    void holdShut(const std::vector<int>& nodes);
    bool heldShut(int i) const { return held_[i] != 0; }

    int nodeCount() const { return static_cast<int>(nodes_.size()); }
    int triangleCount() const { return static_cast<int>(triangles_.size()); }
    const Eigen::Vector3d& node(int i) const { return nodes_[i]; }
    const std::array<int, 3>& triangle(int t) const { return triangles_[t]; }
    const std::vector<int>& trianglesAtNode(int i) const { return nodeTriangles_[i]; }
    double area(int t) const;
    Eigen::Vector3d normal(int t) const;  // crack normal n_c

    bool isFront(int i) const { return unknown_[i] < 0; }
    // On the surface and carrying an opening (not where the front meets the surface).
    bool isMouth(int i) const { return onSurface(i) && unknown_[i] >= 0; }
    bool onSurface(int i) const {
        return surfaceNode_[i] >= 0 || surfaceEdge_[i][0] >= 0 || surfaceTriangle_[i] >= 0;
    }
    int surfaceNodeOf(int i) const { return surfaceNode_[i]; }  // -1: none (or not matched yet)
    // The surface edge (lower node first) whose inside the node lies on; {-1, -1}: none.
    const std::array<int, 2>& surfaceEdgeOf(int i) const { return surfaceEdge_[i]; }
    int surfaceTriangleOf(int i) const { return surfaceTriangle_[i]; }  // inside it; -1: none
    // Whether the sheet edge a-b lies on the surface: both nodes on it and the chord between them
    // no deeper inside than kMouthChordDepth of its length (a sheet edge across a thin wall, from
    // one face to the other, is front). Boundary edges that are mouth edges form the mouth.
    static constexpr double kMouthChordDepth = 0.3;
    bool isMouthEdge(int a, int b) const;
    int unknownOf(int i) const { return unknown_[i]; }  // -1 on the front
    int unknownCount() const { return unknownCount_; }
    const std::vector<int>& nodeOfUnknown() const { return nodeOfUnknown_; }
    // Boundary edges (a, b, t): the boundary edge a-b of triangle t, a -> b in t's orientation.
    // Front edges are those with two front nodes (zero opening at both ends, where the stress
    // intensity is measured); the others have a mouth node at one end (the front's ends, where
    // it crosses the surface) or at both (the mouth).
    struct FrontEdge {
        int a, b, triangle;
    };
    const std::vector<FrontEdge>& frontEdges() const { return frontEdges_; }
    const std::vector<FrontEdge>& boundaryEdges() const { return boundaryEdges_; }
    // Sheets are the edge-connected components, numbered by their lowest triangle (as of the last
    // refreshUnknowns()).
    int sheetOf(int t) const { return sheetOfTriangle_[t]; }
    int sheetCount() const { return sheetCount_; }
    // A new crack mesh with just the given sheets, every node moved by `shift` [m] (carrying
    // incomplete cracks into a fragment's own frame, §5.3). No unknowns are numbered yet.
    CrackMesh extractSheets(const std::vector<int>& sheets, const Eigen::Vector3d& shift) const;

    // The operator sees a crack as extra boundary with normal -n_c and density COD (see
    // FORMULATION.md); node ids are offset by `idOffset` so they never match surface nodes.
    Panel panel(int t, int idOffset) const;
    // Surface curl (-n_c) x grad(psi_k) of the hat of corner k on triangle t.
    Eigen::Vector3d operatorCurl(int t, int k) const;

private:
    std::vector<Eigen::Vector3d> nodes_;
    std::vector<std::array<int, 3>> triangles_;
    std::vector<std::vector<int>> nodeTriangles_;
    std::vector<int> unknown_;
    static constexpr int kUnclassified = -2;
    std::vector<int> surfaceNode_;  // surface node the crack node lies on, -1 none
    std::vector<std::array<int, 2>> surfaceEdge_;
    std::vector<int> surfaceTriangle_;
    std::vector<char> held_;  // held shut (holdShut)
    // (lower, higher node); front chords: sheet edges between surface nodes that are no mouth
    // edges (across a thin wall, or held by holdAsFront)
    std::set<std::pair<int, int>> chordChecked_, frontChords_;
    std::vector<int> nodeOfUnknown_;
    std::vector<FrontEdge> frontEdges_, boundaryEdges_;
    std::vector<int> sheetOfTriangle_;
    int unknownCount_ = 0;
    int sheetCount_ = 0;
};

}  // namespace btfracture
