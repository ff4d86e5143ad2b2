// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexHull.h>

#include <btFracture/core/Error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace btfracture {
namespace {

// ---- Exact orientation on a grid. The points are snapped to a grid of power-of-two cells, at
// most kGridCells per side of their bounding box, and carried as integers in [0, kGridCells]:
// coordinate differences then take 41 bits, the cross terms 82 and the determinant below 124,
// so 128-bit integers evaluate every orientation exactly, with no floating-point filter, in the
// same way on every CPU.

constexpr std::int64_t kGridCells = std::int64_t{1} << 40;

using GridPoint = std::array<std::int64_t, 3>;
using Wide = __int128;

// Sign of (b - a) x (c - a) . (p - a): positive when p lies on the side the normal of the
// counter-clockwise triangle abc points to.
int side(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& p) {
    const std::int64_t ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const std::int64_t vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const std::int64_t wx = p[0] - a[0], wy = p[1] - a[1], wz = p[2] - a[2];
    const Wide xy = Wide{vy} * wz - Wide{vz} * wy, yz = Wide{vz} * wx - Wide{vx} * wz,
               zx = Wide{vx} * wy - Wide{vy} * wx;
    const Wide det = ux * xy + uy * yz + uz * zx;
    return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// The points as grid coordinates: cell = the smallest power of two with kGridCells cells
// covering the largest extent of the bounding box, origin at its low corner.
std::vector<GridPoint> snapToGrid(const std::vector<Eigen::Vector3d>& points) {
    Eigen::Vector3d lo = points.front(), hi = lo;
    for (const auto& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double extent = (hi - lo).maxCoeff();
    int exponent = 0;  // cell = 2^exponent >= extent / kGridCells
    if (extent > 0.0) std::frexp(extent / static_cast<double>(kGridCells), &exponent);
    std::vector<GridPoint> grid(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 3; ++k) grid[i][k] = std::llround(std::ldexp(points[i][k] - lo[k], -exponent));
    return grid;
}

// ---- Quickhull over exact orientations.

struct Face {
    std::array<int, 3> v;                   // counter-clockwise seen from outside
    std::array<int, 3> adj = {-1, -1, -1};  // adj[i]: the face across edge v[i] -> v[i + 1]
    std::vector<int> outside;  // points strictly outside this face (each point in one face's list)
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unnormalised, for choosing the farthest point
    bool alive = true;
    int visible = 0;  // stamp of the last visibility test: +stamp visible, -stamp not
};

class Quickhull {
public:
    // `points` and `grid` (the same points on the grid) must outlive the object; `name` names it
    // in errors.
    Quickhull(const std::vector<Eigen::Vector3d>& points, const std::vector<GridPoint>& grid,
              const std::string& name)
        : p_(points), g_(grid), name_(name) {}

    // The hull's faces; corners are indices into the points.
    void run() {
        simplex();
        for (std::size_t f = 0; f < faces_.size(); ++f)
            if (faces_[f].alive && !faces_[f].outside.empty()) addPoint(static_cast<int>(f));
    }

    // The corners that are extreme points: a point added early can end up inside a flat face or
    // on an edge of the final hull. Such a corner's faces span one plane (inside a face) or two
    // (on an edge, between its two neighbours on the crease); an extreme one's span three or
    // more. Sorted by index.
    std::vector<int> extremeCorners() const {
        std::vector<std::vector<int>> incident(p_.size());
        for (std::size_t f = 0; f < faces_.size(); ++f)
            if (faces_[f].alive)
                for (const int v : faces_[f].v) incident[v].push_back(static_cast<int>(f));
        std::vector<int> extreme;
        for (std::size_t v = 0; v < p_.size(); ++v) {
            if (incident[v].empty()) continue;
            std::vector<int> planes;  // one face of each distinct plane
            for (const int f : incident[v]) {
                const auto samePlane = [&](int g) {
                    for (const int w : faces_[f].v)
                        if (sideOf(faces_[g], w) != 0) return false;
                    return true;
                };
                if (std::none_of(planes.begin(), planes.end(), samePlane)) planes.push_back(f);
                if (planes.size() >= 3) break;
            }
            if (planes.size() >= 3) extreme.push_back(static_cast<int>(v));
        }
        return extreme;
    }

    std::size_t cornerCount() const {
        std::vector<bool> used(p_.size(), false);
        for (const Face& f : faces_)
            if (f.alive)
                for (const int v : f.v) used[v] = true;
        return static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
    }

    TriangleMesh mesh(const std::string& name) const {
        TriangleMesh m;
        m.name = name;
        std::vector<int> index(p_.size(), -1);
        for (const Face& f : faces_) {
            if (!f.alive) continue;
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k) {
                int& i = index[f.v[k]];
                if (i < 0) {
                    i = static_cast<int>(m.vertices.size());
                    m.vertices.push_back(p_[f.v[k]]);
                }
                t[k] = i;
            }
            m.triangles.push_back(t);
        }
        return m;
    }

private:
    int sideOf(const Face& f, int point) const { return side(g_[f.v[0]], g_[f.v[1]], g_[f.v[2]], g_[point]); }

    [[noreturn]] void flat(const char* what) const {
        std::ostringstream out;
        out << name_ << ": convex hull of " << p_.size() << " points is flat (" << what << ", no volume)";
        throw Error(out.str());
    }

    void simplex() {
        const int n = static_cast<int>(p_.size());
        int i0 = 0;
        for (int i = 1; i < n; ++i)
            if (p_[i].x() < p_[i0].x()) i0 = i;
        int i1 = i0;
        double best = 0.0;
        for (int i = 0; i < n; ++i) {
            const double distance = (p_[i] - p_[i0]).squaredNorm();
            if (distance > best) {
                best = distance;
                i1 = i;
            }
        }
        if (i1 == i0) flat("all points coincide");
        int i2 = -1;
        best = 0.0;
        for (int i = 0; i < n; ++i) {
            const double area = (p_[i] - p_[i0]).cross(p_[i1] - p_[i0]).squaredNorm();
            if (area > best) {
                best = area;
                i2 = i;
            }
        }
        if (i2 < 0) flat("all points on a line");
        int i3 = -1;
        best = 0.0;
        for (int i = 0; i < n; ++i) {
            const double volume = std::abs((p_[i1] - p_[i0]).cross(p_[i2] - p_[i0]).dot(p_[i] - p_[i0]));
            if (volume > best && side(g_[i0], g_[i1], g_[i2], g_[i]) != 0) {
                best = volume;
                i3 = i;
            }
        }
        if (i3 < 0)
            for (int i = 0; i < n && i3 < 0; ++i)
                if (side(g_[i0], g_[i1], g_[i2], g_[i]) != 0) i3 = i;
        if (i3 < 0) flat("all points in a plane");

        const std::array<int, 4> corner = {i0, i1, i2, i3};
        const std::array<std::array<int, 4>, 4> tetra = {
            {{0, 1, 2, 3}, {0, 3, 1, 2}, {1, 3, 2, 0}, {0, 2, 3, 1}}};
        for (const auto& t : tetra) {
            Face f;
            f.v = {corner[t[0]], corner[t[1]], corner[t[2]]};
            if (side(g_[f.v[0]], g_[f.v[1]], g_[f.v[2]], g_[corner[t[3]]]) > 0) std::swap(f.v[1], f.v[2]);
            faces_.push_back(f);
        }
        for (int f = 0; f < 4; ++f)
            for (int i = 0; i < 3; ++i)
                faces_[f].adj[i] = faceAcross(f, faces_[f].v[(i + 1) % 3], faces_[f].v[i], 4);
        for (Face& f : faces_) setNormal(f);
        std::vector<int> rest;
        for (int i = 0; i < n; ++i)
            if (i != i0 && i != i1 && i != i2 && i != i3) rest.push_back(i);
        assign(rest, 0);
    }

    // The face among the first `count` that has the directed edge from -> to.
    int faceAcross(int self, int from, int to, int count) const {
        for (int g = 0; g < count; ++g) {
            if (g == self) continue;
            for (int j = 0; j < 3; ++j)
                if (faces_[g].v[j] == from && faces_[g].v[(j + 1) % 3] == to) return g;
        }
        throw Error(name_ + ": convex hull: broken initial simplex");
    }

    void setNormal(Face& f) const { f.normal = (p_[f.v[1]] - p_[f.v[0]]).cross(p_[f.v[2]] - p_[f.v[0]]); }

    // Each point goes to the first live face from `firstFace` on that it lies strictly outside;
    // points outside none are inside the hull (or on it) and are dropped.
    void assign(const std::vector<int>& points, std::size_t firstFace) {
        for (const int q : points)
            for (std::size_t f = firstFace; f < faces_.size(); ++f)
                if (faces_[f].alive && sideOf(faces_[f], q) > 0) {
                    faces_[f].outside.push_back(q);
                    break;
                }
    }

    bool isVisible(int f, int eye) {
        Face& face = faces_[f];
        if (face.visible == stamp_) return true;
        if (face.visible == -stamp_) return false;
        const bool visible = sideOf(face, eye) > 0;
        face.visible = visible ? stamp_ : -stamp_;
        return visible;
    }

    void addPoint(int start) {
        Face& first = faces_[start];
        int eye = first.outside.front();
        double farthest = -1.0;
        for (const int q : first.outside) {
            const double d = first.normal.dot(p_[q] - p_[first.v[0]]);
            if (d > farthest) {
                farthest = d;
                eye = q;
            }
        }
        ++stamp_;
        faces_[start].visible = stamp_;
        // Depth-first over the visible faces, each entered across one edge and left across the
        // others in order: the edges to faces that are not visible come out as one closed loop,
        // counter-clockwise seen from the eye.
        struct Visit {
            int face, entry, k;
        };
        std::vector<std::pair<int, int>> horizon;  // (visible face, edge index)
        std::vector<int> visibleFaces = {start};
        std::vector<Visit> stack = {{start, 0, 0}};
        while (!stack.empty()) {
            Visit& top = stack.back();
            const bool root = stack.size() == 1;
            if (top.k == (root ? 3 : 2)) {
                stack.pop_back();
                continue;
            }
            const int edge = (top.entry + (root ? 0 : 1) + top.k++) % 3;
            const int face = top.face;
            const int next = faces_[face].adj[edge];
            const bool seen = faces_[next].visible == stamp_;
            if (isVisible(next, eye)) {
                if (seen) continue;
                visibleFaces.push_back(next);
                stack.push_back(
                    {next, edgeIndex(next, faces_[face].v[(edge + 1) % 3], faces_[face].v[edge]), 0});
            } else {
                horizon.emplace_back(face, edge);
            }
        }
        const int count = static_cast<int>(horizon.size());
        for (int k = 0; k < count; ++k) {
            const auto [f, e] = horizon[k];
            const auto [g, h] = horizon[(k + 1) % count];
            if (faces_[f].v[(e + 1) % 3] != faces_[g].v[h])
                throw Error(name_ + ": convex hull: open horizon");
        }
        std::vector<int> orphans;
        for (const int f : visibleFaces) {
            faces_[f].alive = false;
            for (const int q : faces_[f].outside)
                if (q != eye) orphans.push_back(q);
            faces_[f].outside.clear();
            faces_[f].outside.shrink_to_fit();
        }
        const std::size_t firstNew = faces_.size();
        for (int k = 0; k < count; ++k) {
            const auto [f, e] = horizon[k];
            const int a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3], across = faces_[f].adj[e];
            Face n;
            n.v = {a, b, eye};
            n.adj = {across, static_cast<int>(firstNew) + (k + 1) % count,
                     static_cast<int>(firstNew) + (k + count - 1) % count};
            setNormal(n);
            faces_[across].adj[edgeIndex(across, b, a)] = static_cast<int>(faces_.size());
            faces_.push_back(n);
        }
        assign(orphans, firstNew);
    }

    int edgeIndex(int face, int from, int to) const {
        for (int j = 0; j < 3; ++j)
            if (faces_[face].v[j] == from && faces_[face].v[(j + 1) % 3] == to) return j;
        throw Error(name_ + ": convex hull: inconsistent faces");
    }

    const std::vector<Eigen::Vector3d>& p_;
    const std::vector<GridPoint>& g_;
    std::string name_;
    std::vector<Face> faces_;
    int stamp_ = 0;
};

}  // namespace

TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name) {
    for (const auto& p : points)
        if (!p.allFinite() || p.cwiseAbs().maxCoeff() > 1e300)
            throw Error(name + ": convex hull input has a non-finite point or one beyond 1e300");
    if (points.size() < 4) {
        std::ostringstream out;
        out << name << ": convex hull of " << points.size() << " points spans no volume (need >= 4)";
        throw Error(out.str());
    }
    const std::vector<GridPoint> grid = snapToGrid(points);
    Quickhull hull(points, grid, name);
    hull.run();
    const std::vector<int> extreme = hull.extremeCorners();
    if (extreme.size() == hull.cornerCount()) return hull.mesh(name);
    // Again over the extreme corners alone (on the same grid), so that every corner is one.
    std::vector<Eigen::Vector3d> corners;
    std::vector<GridPoint> cornerGrid;
    for (const int i : extreme) {
        corners.push_back(points[i]);
        cornerGrid.push_back(grid[i]);
    }
    Quickhull lean(corners, cornerGrid, name);
    lean.run();
    return lean.mesh(name);
}

double convexHullVolume(const std::vector<Eigen::Vector3d>& points, const std::string& name) {
    for (const auto& p : points)
        if (!p.allFinite() || p.cwiseAbs().maxCoeff() > 1e300)
            throw Error(name + ": convex hull input has a non-finite point or one beyond 1e300");
    TriangleMesh hull;
    try {
        hull = convexHullMesh(points, name);
    } catch (const Error&) {
        return 0.0;  // flat
    }
    // Tetrahedra from the first corner to every face: the hull's own frame, not the origin's.
    const Eigen::Vector3d& o = hull.vertices.front();
    double six = 0.0;
    for (const auto& t : hull.triangles)
        six += (hull.vertices[t[0]] - o).dot((hull.vertices[t[1]] - o).cross(hull.vertices[t[2]] - o));
    return six / 6.0;
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
