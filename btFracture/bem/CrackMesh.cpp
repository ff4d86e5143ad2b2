// SPDX-License-Identifier: Zlib
#include <btFracture/bem/CrackMesh.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/UnionFind.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <sstream>

namespace btfracture {

int CrackMesh::addNode(const Eigen::Vector3d& position) {
    if (!position.allFinite()) throw Error("CrackMesh: crack node position is not finite");
    nodes_.push_back(position);
    nodeTriangles_.emplace_back();
    unknown_.push_back(-1);
    surfaceNode_.push_back(kUnclassified);
    surfaceEdge_.push_back({-1, -1});
    surfaceTriangle_.push_back(-1);
    held_.push_back(0);
    return nodeCount() - 1;
}

int CrackMesh::addTriangle(int a, int b, int c) {
    for (int v : {a, b, c})
        if (v < 0 || v >= nodeCount())
            throw Error("CrackMesh: triangle corner " + std::to_string(v) + " out of range");
    if (a == b || b == c || a == c) throw Error("CrackMesh: triangle with a repeated corner");
    triangles_.push_back({a, b, c});
    const int t = triangleCount() - 1;
    if (!(area(t) > 0.0)) throw Error("CrackMesh: degenerate crack triangle " + std::to_string(t));
    for (int v : {a, b, c}) nodeTriangles_[v].push_back(t);
    return t;
}

bool CrackMesh::isMouthEdge(int a, int b) const {
    return onSurface(a) && onSurface(b) && !frontChords_.count({std::min(a, b), std::max(a, b)});
}

double CrackMesh::area(int t) const {
    const auto& tri = triangles_[t];
    return 0.5 * (nodes_[tri[1]] - nodes_[tri[0]]).cross(nodes_[tri[2]] - nodes_[tri[0]]).norm();
}

Eigen::Vector3d CrackMesh::normal(int t) const {
    const auto& tri = triangles_[t];
    return (nodes_[tri[1]] - nodes_[tri[0]]).cross(nodes_[tri[2]] - nodes_[tri[0]]).normalized();
}

CrackMesh CrackMesh::extractSheets(const std::vector<int>& sheets, const Eigen::Vector3d& shift) const {
    CrackMesh out;
    std::vector<int> newIndex(nodes_.size(), -1);
    for (int t = 0; t < triangleCount(); ++t) {
        if (std::find(sheets.begin(), sheets.end(), sheetOfTriangle_[t]) == sheets.end()) continue;
        std::array<int, 3> tri;
        for (int k = 0; k < 3; ++k) {
            int& index = newIndex[triangles_[t][k]];
            if (index < 0) index = out.addNode(nodes_[triangles_[t][k]] + shift);
            tri[k] = index;
        }
        out.addTriangle(tri[0], tri[1], tri[2]);
    }
    return out;
}

Panel CrackMesh::panel(int t, int idOffset) const {
    const auto& tri = triangles_[t];
    return Panel{{tri[0] + idOffset, tri[1] + idOffset, tri[2] + idOffset},
                 {nodes_[tri[0]], nodes_[tri[1]], nodes_[tri[2]]},
                 -normal(t),
                 area(t)};
}

Eigen::Vector3d CrackMesh::operatorCurl(int t, int k) const {
    const auto& tri = triangles_[t];
    const Eigen::Vector3d n = normal(t);
    const double twiceArea = 2.0 * area(t);
    // grad(psi_k) = n_c x (opposite edge, counter-clockwise) / (2A); the operator normal is -n_c.
    const Eigen::Vector3d edge = nodes_[tri[(k + 2) % 3]] - nodes_[tri[(k + 1) % 3]];
    const Eigen::Vector3d grad = n.cross(edge) / twiceArea;
    return (-n).cross(grad);
}

std::vector<int> CrackMesh::refreshUnknowns(const SurfaceMesh& body) {
    const double tolerance = 1e-9 * body.radius();
    for (int i = 0; i < nodeCount(); ++i) {
        if (surfaceNode_[i] != kUnclassified) continue;
        surfaceNode_[i] = -1;
        const SurfaceMesh::Nearest nearest = body.nearest(nodes_[i]);
        if (nearest.distance > tolerance) continue;
        const auto& tri = body.triangle(nearest.triangle);
        for (int s : tri)
            if ((body.node(s) - nodes_[i]).norm() <= tolerance) surfaceNode_[i] = s;
        for (int k = 0; k < 3 && surfaceNode_[i] < 0; ++k) {
            const Eigen::Vector3d a = body.node(tri[k]), ab = body.node(tri[(k + 1) % 3]) - a;
            const double t = (nodes_[i] - a).dot(ab) / ab.squaredNorm();
            if (t > 0.0 && t < 1.0 && (a + t * ab - nodes_[i]).norm() <= tolerance)
                surfaceEdge_[i] = {std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])};
        }
        if (surfaceNode_[i] < 0 && surfaceEdge_[i][0] < 0) surfaceTriangle_[i] = nearest.triangle;
    }
    // An edge between two nodes on the surface whose chord runs deeper inside than kMouthChordDepth
    // of its length (across a thin wall, from one face to the opposite one) is no mouth edge.
    for (const auto& tri : triangles_)
        for (int k = 0; k < 3; ++k) {
            const int a = std::min(tri[k], tri[(k + 1) % 3]), b = std::max(tri[k], tri[(k + 1) % 3]);
            if (!onSurface(a) || !onSurface(b) || !chordChecked_.insert({a, b}).second) continue;
            const double depth = body.nearest(0.5 * (nodes_[a] + nodes_[b])).distance;
            if (depth > kMouthChordDepth * (nodes_[b] - nodes_[a]).norm() + tolerance)
                frontChords_.insert({a, b});
        }
    return refreshUnknowns();
}

void CrackMesh::holdShut(const std::vector<int>& nodes) {
    for (int i : nodes) {
        if (unknown_[i] >= 0)
            throw Error("CrackMesh: node " + std::to_string(i) +
                        " already carries an opening; it cannot be held shut");
        held_[i] = 1;
    }
}

std::vector<int> CrackMesh::holdAsFront(const std::vector<std::pair<int, int>>& edges, int kept) {
    for (const auto& [a, b] : edges) frontChords_.insert({std::min(a, b), std::max(a, b)});
    for (int k = kept; k < unknownCount_; ++k) unknown_[nodeOfUnknown_[k]] = -1;
    nodeOfUnknown_.resize(kept);
    unknownCount_ = kept;
    return refreshUnknowns();
}

std::vector<int> CrackMesh::refreshUnknowns() {
    // Edge census: a boundary edge is used once, an interior edge twice in opposite directions.
    std::map<std::pair<int, int>, std::vector<std::pair<int, bool>>> edges;  // -> (triangle, forward)
    for (int t = 0; t < triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].emplace_back(t, a < b);
        }
    std::vector<char> onFront(nodes_.size(), 0);
    boundaryEdges_.clear();
    UnionFind sheets(static_cast<int>(triangles_.size()));
    for (const auto& [edge, uses] : edges) {
        if (uses.size() > 2 || (uses.size() == 2 && uses[0].second == uses[1].second)) {
            std::ostringstream msg;
            msg << "CrackMesh: edge " << edge.first << "-" << edge.second
                << (uses.size() > 2 ? " is shared by more than two crack triangles"
                                    : " is inconsistently oriented");
            throw Error(msg.str());
        }
        if (uses.size() == 1) {
            onFront[edge.first] = onFront[edge.second] = 1;
            const int t = uses[0].first;
            const bool forward = uses[0].second;
            boundaryEdges_.push_back(
                {forward ? edge.first : edge.second, forward ? edge.second : edge.first, t});
        } else {
            sheets.unite(uses[0].first, uses[1].first);
        }
    }
    // Sheets (edge-connected components).
    sheetOfTriangle_.assign(triangles_.size(), -1);
    std::map<int, int> sheetOfRoot;
    for (int t = 0; t < triangleCount(); ++t) {
        const auto it = sheetOfRoot.emplace(sheets.find(t), static_cast<int>(sheetOfRoot.size())).first;
        sheetOfTriangle_[t] = it->second;
    }
    sheetCount_ = static_cast<int>(sheetOfRoot.size());
    // Boundary nodes on surface nodes are mouth nodes, not front, except next to a front node
    // off the surface: there the front meets the surface.
    std::vector<char> frontEnd(nodes_.size(), 0);
    for (const FrontEdge& e : boundaryEdges_) {
        if (isMouthEdge(e.a, e.b)) continue;
        if (onSurface(e.a) && unknown_[e.a] < 0) frontEnd[e.a] = 1;
        if (onSurface(e.b) && unknown_[e.b] < 0) frontEnd[e.b] = 1;
    }
    for (int i = 0; i < nodeCount(); ++i)
        if (onSurface(i) && !frontEnd[i]) onFront[i] = 0;
    frontEdges_.clear();
    for (const FrontEdge& e : boundaryEdges_)
        if (onFront[e.a] && onFront[e.b]) frontEdges_.push_back(e);
    std::vector<int> activated;
    for (int i = 0; i < nodeCount(); ++i) {
        if (onFront[i] && unknown_[i] >= 0)
            throw Error("CrackMesh: node " + std::to_string(i) +
                        " returned to the front; sheets may only grow");
        if (!onFront[i] && unknown_[i] < 0 && !nodeTriangles_[i].empty() && !held_[i]) {
            unknown_[i] = unknownCount_++;
            nodeOfUnknown_.push_back(i);
            activated.push_back(i);
        }
    }
    return activated;
}

}  // namespace btfracture
