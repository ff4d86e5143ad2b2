// SPDX-License-Identifier: Zlib
#pragma once
// Half-edge connectivity of a closed, manifold, consistently oriented triangle mesh with the
// local edits that remeshing needs: edge split, edge collapse and edge flip, plus previews of
// what a collapse or flip would do to the geometry before it is made.
//
// Halfedge h belongs to face h / 3 and runs from origin(h) to target(h) = origin(next(h)).
// Removed faces and vertices stay as dead slots until compact(); every loop over slots runs in
// index order, so edits are deterministic.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace btfracture {

class HalfEdgeMesh {
public:
    // Throws btfracture::Error naming mesh.name unless the mesh is closed, manifold and
    // consistently oriented (core/MeshCheck.h). Vertices used by no triangle are dropped.
    explicit HalfEdgeMesh(const TriangleMesh& mesh);

    // Live faces and vertices, renumbered in slot order.
    TriangleMesh toTriangleMesh(const std::string& name) const;
    // Drops dead slots (keeps the order of live ones); invalidates all indices.
    void compact();

    int vertexSlots() const { return static_cast<int>(position_.size()); }
    int faceSlots() const { return static_cast<int>(origin_.size()) / 3; }
    int halfedgeSlots() const { return static_cast<int>(origin_.size()); }
    int faceCount() const { return liveFaces_; }
    int vertexCount() const { return liveVertices_; }
    bool vertexAlive(int v) const { return outgoing_[v] >= 0; }
    bool faceAlive(int f) const { return origin_[3 * f] >= 0; }
    bool halfedgeAlive(int h) const { return origin_[h] >= 0; }

    static int face(int h) { return h / 3; }
    static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
    static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
    int twin(int h) const { return twin_[h]; }
    int origin(int h) const { return origin_[h]; }
    int target(int h) const { return origin_[next(h)]; }
    // Vertex opposite halfedge h in its face.
    int apex(int h) const { return origin_[prev(h)]; }
    int outgoing(int v) const { return outgoing_[v]; }
    // Next outgoing halfedge of the same origin, turning clockwise seen from outside.
    int nextOutgoing(int h) const { return next(twin_[h]); }

    const Eigen::Vector3d& position(int v) const { return position_[v]; }
    void setPosition(int v, const Eigen::Vector3d& p) { position_[v] = p; }
    std::array<int, 3> faceVertices(int f) const {
        return {origin_[3 * f], origin_[3 * f + 1], origin_[3 * f + 2]};
    }

    int valence(int v) const;
    double edgeLength(int h) const { return (position_[target(h)] - position_[origin(h)]).norm(); }
    // Cross product of two edges: twice the area times the unit normal.
    Eigen::Vector3d faceAreaNormal(int f) const;
    // Area-weighted unit normal (zero vector if the incident triangles cancel out).
    Eigen::Vector3d vertexNormal(int v) const;
    // Smallest interior angle of face f [rad].
    double faceMinAngle(int f) const;
    // Smallest angle over the faces around v [rad].
    double minAngleAroundVertex(int v) const;
    bool adjacent(int u, int v) const;

    // Calls f(h) for each outgoing halfedge of v, in order.
    template <class F>
    void forEachOutgoing(int v, F&& f) const {
        const int first = outgoing_[v];
        int h = first;
        int steps = 0;
        do {
            f(h);
            h = nextOutgoing(h);
            if (++steps > halfedgeSlots()) throwOpenRing(v);  // an edit broke the ring: never loop
        } while (h != first);
    }

    // Geometry of the faces an edit would leave around the moved vertices.
    struct EditPreview {
        double minAngle = 0.0;         // smallest angle of the new faces [rad]
        double maxEdgeLength = 0.0;    // longest edge at the moved vertex (collapse) or the new edge (flip)
        double minNormalCosine = 1.0;  // worst cosine between a face's new and old unit normals
        double deviation = 0.0;        // how far the surface moves: distance of the removed vertex
                                 // positions (collapse) or the old edge's midpoint (flip) to the new faces
    };

    // Topology: a collapse of h is allowed when origin and target share exactly the two apex
    // vertices as neighbours (link condition), both apexes keep at least three neighbours and the
    // mesh keeps more than 4 vertices.
    bool collapseKeepsManifold(int h) const;
    // Faces around both ends of h after origin(h) and target(h) merge at p.
    EditPreview previewCollapse(int h, const Eigen::Vector3d& p) const;
    // Smallest angle over the faces around both ends of h, including the two faces at h.
    double minAngleAroundEdge(int h) const;
    // Removes origin(h) and the two faces at h; target(h) moves to p and is returned.
    int collapseEdge(int h, const Eigen::Vector3d& p);

    // Topology: the new edge between the two apexes must not exist yet and both ends of h must
    // keep valence >= 3.
    bool flipKeepsManifold(int h) const;
    // The two faces after the flip (minNormalCosine compares each new face with both old ones).
    EditPreview previewFlip(int h) const;
    void flipEdge(int h);

    // Inserts a vertex at p on the edge of h, splitting both faces at h; returns the vertex.
    int splitEdge(int h, const Eigen::Vector3d& p);

private:
    [[noreturn]] void throwOpenRing(int v) const;
    void link(int h, int g) {
        twin_[h] = g;
        twin_[g] = h;
    }
    int addFace(int a, int b, int c);

    std::vector<Eigen::Vector3d> position_;
    std::vector<int> outgoing_;  // one outgoing halfedge per vertex, -1 when dead
    std::vector<int> origin_;    // per halfedge, -1 when its face is dead
    std::vector<int> twin_;
    int liveFaces_ = 0;
    int liveVertices_ = 0;
};

}  // namespace btfracture
