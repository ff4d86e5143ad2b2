// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/ConvexHull.h>

#include <btFracture/core/Error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace btfracture {
namespace {

// ---- Exact orientation (expansion arithmetic: every value is a sum of non-overlapping doubles
// in increasing magnitude; sums and products are exact as long as no product underflows).
// Expansions live on the stack: the exact path runs for every (near-)coplanar point of a hull,
// which cut faces and voxel-aligned level-set surfaces have by the thousand.

// The largest expansion side() builds: differences have <= 2 components, a product of m and n
// components <= 1 + 2 m n (so <= 9 for two differences), a cross term <= 18, a difference times a
// cross term <= 73, the determinant <= 219.
constexpr int kMaxComponents = 224;

struct Expansion {
    double c[kMaxComponents];
    int n = 0;
};

void twoSum(double a, double b, double& sum, double& error) {
    sum = a + b;
    const double bVirtual = sum - a, aVirtual = sum - bVirtual;
    error = (a - aVirtual) + (b - bVirtual);
}

void difference(double a, double b, Expansion& h) {
    const double x = a - b;
    const double bVirtual = a - x, aVirtual = x + bVirtual;
    const double y = (a - aVirtual) + (bVirtual - b);
    h.n = 0;
    if (y != 0.0) h.c[h.n++] = y;
    h.c[h.n++] = x;
}

// e += b, in place (each component is read before its slot or a later one is written).
void grow(Expansion& e, double b) {
    double q = b;
    int n = 0;
    for (int i = 0; i < e.n; ++i) {
        double sum, error;
        twoSum(q, e.c[i], sum, error);
        q = sum;
        if (error != 0.0) e.c[n++] = error;
    }
    if (q != 0.0 || n == 0) e.c[n++] = q;
    e.n = n;
}

// e += f
void add(Expansion& e, const Expansion& f) {
    for (int i = 0; i < f.n; ++i) grow(e, f.c[i]);
}

// h = e * b
void scale(const Expansion& e, double b, Expansion& h) {
    h.n = 0;
    double q = e.c[0] * b;
    double error = std::fma(e.c[0], b, -q);
    if (error != 0.0) h.c[h.n++] = error;
    for (int i = 1; i < e.n; ++i) {
        const double product = e.c[i] * b, productError = std::fma(e.c[i], b, -product);
        double s;
        twoSum(q, productError, s, error);
        if (error != 0.0) h.c[h.n++] = error;
        q = product + s;  // |product| >= |s|: exact with the error below
        error = s - (q - product);
        if (error != 0.0) h.c[h.n++] = error;
    }
    if (q != 0.0 || h.n == 0) h.c[h.n++] = q;
}

// total = e * f
void product(const Expansion& e, const Expansion& f, Expansion& total) {
    total.n = 1;
    total.c[0] = 0.0;
    Expansion scaled;
    for (int i = 0; i < f.n; ++i) {
        scale(e, f.c[i], scaled);
        add(total, scaled);
    }
}

void negate(Expansion& e) {
    for (int i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
}

int sign(const Expansion& e) {
    for (int i = e.n - 1; i >= 0; --i)
        if (e.c[i] != 0.0) return e.c[i] > 0.0 ? 1 : -1;
    return 0;
}

// Sign of (b - a) x (c - a) . (p - a): positive when p lies on the side the normal of the
// counter-clockwise triangle abc points to. A floating-point filter first; exact when it cannot
// decide.
int side(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
         const Eigen::Vector3d& p) {
    const Eigen::Vector3d u = b - a, v = c - a, w = p - a;
    const double xy = v.y() * w.z() - v.z() * w.y(), yz = v.z() * w.x() - v.x() * w.z(),
                 zx = v.x() * w.y() - v.y() * w.x();
    const double det = u.x() * xy + u.y() * yz + u.z() * zx;
    const double permanent = std::abs(u.x()) * (std::abs(v.y() * w.z()) + std::abs(v.z() * w.y())) +
                             std::abs(u.y()) * (std::abs(v.z() * w.x()) + std::abs(v.x() * w.z())) +
                             std::abs(u.z()) * (std::abs(v.x() * w.y()) + std::abs(v.y() * w.x()));
    // Round-off of the differences, products and sums stays below 8 eps of the permanent.
    const double bound = 8.0 * std::numeric_limits<double>::epsilon() * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    std::array<Expansion, 3> U, V, W;
    for (int k = 0; k < 3; ++k) {
        difference(b[k], a[k], U[k]);
        difference(c[k], a[k], V[k]);
        difference(p[k], a[k], W[k]);
    }
    Expansion exact, cross, term, negative;
    exact.n = 0;
    // cross(i, j) = V_i W_j - V_j W_i; exact = U_0 cross(1, 2) + U_1 cross(2, 0) + U_2 cross(0, 1)
    const int pairs[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    for (int k = 0; k < 3; ++k) {
        const int i = pairs[k][0], j = pairs[k][1];
        product(V[i], W[j], cross);
        product(V[j], W[i], negative);
        negate(negative);
        add(cross, negative);
        product(U[k], cross, term);
        if (k == 0)
            exact = term;
        else
            add(exact, term);
    }
    return sign(exact);
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
    // `points` must outlive the object; `name` names it in errors.
    Quickhull(const std::vector<Eigen::Vector3d>& points, const std::string& name)
        : p_(points), name_(name) {}

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
    int sideOf(const Face& f, int point) const { return side(p_[f.v[0]], p_[f.v[1]], p_[f.v[2]], p_[point]); }

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
            if (volume > best && side(p_[i0], p_[i1], p_[i2], p_[i]) != 0) {
                best = volume;
                i3 = i;
            }
        }
        if (i3 < 0)
            for (int i = 0; i < n && i3 < 0; ++i)
                if (side(p_[i0], p_[i1], p_[i2], p_[i]) != 0) i3 = i;
        if (i3 < 0) flat("all points in a plane");

        const std::array<int, 4> corner = {i0, i1, i2, i3};
        const std::array<std::array<int, 4>, 4> tetra = {
            {{0, 1, 2, 3}, {0, 3, 1, 2}, {1, 3, 2, 0}, {0, 2, 3, 1}}};
        for (const auto& t : tetra) {
            Face f;
            f.v = {corner[t[0]], corner[t[1]], corner[t[2]]};
            if (side(p_[f.v[0]], p_[f.v[1]], p_[f.v[2]], p_[corner[t[3]]]) > 0) std::swap(f.v[1], f.v[2]);
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
    std::string name_;
    std::vector<Face> faces_;
    int stamp_ = 0;
};

}  // namespace

TriangleMesh convexHullMesh(const std::vector<Eigen::Vector3d>& points, const std::string& name) {
    for (const auto& p : points)
        if (!p.allFinite()) throw Error(name + ": convex hull input has a non-finite point");
    if (points.size() < 4) {
        std::ostringstream out;
        out << name << ": convex hull of " << points.size() << " points spans no volume (need >= 4)";
        throw Error(out.str());
    }
    Quickhull hull(points, name);
    hull.run();
    const std::vector<int> extreme = hull.extremeCorners();
    if (extreme.size() == hull.cornerCount()) return hull.mesh(name);
    // Again over the extreme corners alone, so that every corner is one.
    std::vector<Eigen::Vector3d> corners;
    for (const int i : extreme) corners.push_back(points[i]);
    Quickhull lean(corners, name);
    lean.run();
    return lean.mesh(name);
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
