// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexHull.h>

#include <btFracture/core/Error.h>

#include <LinearMath/btConvexHullComputer.h>

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>

namespace btfracture {

TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name) {
    for (const auto& p : points)
        if (!p.allFinite()) throw Error(name + ": convex hull input has a non-finite point");
    if (points.size() < 4) {
        std::ostringstream out;
        out << name << ": convex hull of " << points.size() << " points spans no volume (need >= 4)";
        throw Error(out.str());
    }
    std::vector<double> coords;
    coords.reserve(3 * points.size());
    for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    btConvexHullComputer hull;
    hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)), static_cast<int>(points.size()), 0, 0);

    TriangleMesh mesh;
    mesh.name = name;
    // The hull's corners are input points: take them in double precision.
    for (int i = 0; i < hull.vertices.size(); ++i)
        mesh.vertices.push_back(points[hull.original_vertex_index[i]]);
    for (int f = 0; f < hull.faces.size(); ++f) {
        const btConvexHullComputer::Edge* start = &hull.edges[hull.faces[f]];
        std::vector<int> polygon;
        const btConvexHullComputer::Edge* e = start;
        do {
            polygon.push_back(e->getSourceVertex());
            e = e->getNextEdgeOfFace();
        } while (e != start);
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
            mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
    double volume = 0.0;
    for (const auto& t : mesh.triangles)
        volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    if (mesh.triangles.size() < 4 || !(std::abs(volume) > 0.0)) {
        std::ostringstream out;
        out << name << ": convex hull of " << points.size() << " points is flat (" << mesh.triangles.size()
            << " triangles, no volume)";
        throw Error(out.str());
    }
    if (volume < 0.0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

bool isConvex(const TriangleMesh& mesh, double relativeTolerance) {
    if (mesh.vertices.empty()) return false;
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double tolerance = relativeTolerance * (hi - lo).norm();
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d& a = mesh.vertices[t[0]];
        const Eigen::Vector3d n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
        const double length = n.norm();
        if (!(length > 0.0)) continue;
        for (const auto& v : mesh.vertices)
            if (n.dot(v - a) / length > tolerance) return false;
    }
    return true;
}

}  // namespace btfracture
