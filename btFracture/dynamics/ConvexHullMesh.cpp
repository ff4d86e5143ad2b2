#include <btFracture/dynamics/ConvexHullMesh.h>

#include <btFracture/core/Error.h>

#include <sstream>

namespace btfracture {

TriangleMesh boxMesh(const Eigen::Vector3d& h, const std::string& name) {
    if (!h.allFinite() || !(h.minCoeff() > 0.0)) {
        std::ostringstream out;
        out << name << ": box half extents (" << h.transpose() << ") must be finite and positive";
        throw Error(out.str());
    }
    TriangleMesh mesh;
    mesh.name = name;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                                   (i & 4) ? h.z() : -h.z());
    // Each face as a quad (corner bits), counter-clockwise seen from outside.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
    }
    return mesh;
}

}  // namespace btfracture
