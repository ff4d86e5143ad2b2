// SPDX-License-Identifier: Zlib
// LevelSetBody: building the level set, mass integrals, queries, curvature, meshing and crack
// cuts. One of the two translation units that include OpenVDB (the other: LevelSetFragments.cpp).
#include <btFracture/geometry/LevelSetBody.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/geometry/MeshDebris.h>
#include <btFracture/geometry/MeshDecimation.h>
#include <btFracture/geometry/internal/LevelSetGrids.h>

#include <openvdb/io/File.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <Eigen/Geometry>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <sstream>
#include <unordered_map>

namespace btfracture {
namespace levelset {
namespace {

void initializeOpenVdbOnce() {
    static std::once_flag flag;
    std::call_once(flag, [] { openvdb::initialize(); });
}

std::string describePoint(const Eigen::Vector3d& p) {
    std::ostringstream out;
    out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return out.str();
}

// Triangles given to OpenVDB in index space (double precision, no copy of the mesh).
struct IndexSpaceTriangles {
    const std::vector<Eigen::Vector3d>& vertices;
    const std::vector<std::array<int, 3>>& triangles;
    double inverseVoxelSize;

    size_t polygonCount() const { return triangles.size(); }
    size_t pointCount() const { return vertices.size(); }
    size_t vertexCount(size_t) const { return 3; }
    void getIndexSpacePoint(size_t n, size_t v, openvdb::Vec3d& pos) const {
        const Eigen::Vector3d& p = vertices[triangles[n][v]];
        pos = openvdb::Vec3d(p.x() * inverseVoxelSize, p.y() * inverseVoxelSize, p.z() * inverseVoxelSize);
    }
};

// The parts of the sheet's triangles inside the box [lo, hi] (Sutherland-Hodgman against the six
// planes, polygons fanned into triangles): only they can cut the body, and a sheet much larger
// than the body would otherwise cost a distance field over all of it.
TriangleMesh clipToBox(const TriangleMesh& sheet, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    TriangleMesh clipped;
    clipped.name = sheet.name;
    std::vector<Eigen::Vector3d> polygon, next;
    for (const auto& t : sheet.triangles) {
        polygon = {sheet.vertices[t[0]], sheet.vertices[t[1]], sheet.vertices[t[2]]};
        for (int axis = 0; axis < 3 && !polygon.empty(); ++axis)
            for (int side = 0; side < 2 && !polygon.empty(); ++side) {
                // Inside: x[axis] >= lo[axis] (side 0) or x[axis] <= hi[axis] (side 1).
                auto inside = [&](const Eigen::Vector3d& x) {
                    return side == 0 ? x[axis] - lo[axis] : hi[axis] - x[axis];
                };
                next.clear();
                for (size_t i = 0; i < polygon.size(); ++i) {
                    const Eigen::Vector3d& p = polygon[i];
                    const Eigen::Vector3d& q = polygon[(i + 1) % polygon.size()];
                    const double dp = inside(p), dq = inside(q);
                    if (dp >= 0) next.push_back(p);
                    if ((dp >= 0) != (dq >= 0)) next.push_back(p + dp / (dp - dq) * (q - p));
                }
                polygon.swap(next);
            }
        if (polygon.size() < 3) continue;
        const int base = static_cast<int>(clipped.vertices.size());
        clipped.vertices.insert(clipped.vertices.end(), polygon.begin(), polygon.end());
        for (int k = 1; k + 1 < static_cast<int>(polygon.size()); ++k)
            clipped.triangles.push_back({base, base + k, base + k + 1});
    }
    return clipped;
}

// Exact signed distance to a closed, consistently oriented mesh from its closest triangle, signed
// with the angle-weighted pseudonormal of the closest feature (Baerentzen & Aanaes 2005).
class PseudonormalSign {
public:
    explicit PseudonormalSign(const TriangleMesh& mesh)
        : mesh_(mesh), vertexNormal_(mesh.vertices.size(), Eigen::Vector3d::Zero()) {
        faceNormal_.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles) {
            const Eigen::Vector3d n = triangleNormal(t);
            faceNormal_.push_back(n);
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector3d& p = mesh.vertices[t[k]];
                const Eigen::Vector3d e1 = (mesh.vertices[t[(k + 1) % 3]] - p).normalized();
                const Eigen::Vector3d e2 = (mesh.vertices[t[(k + 2) % 3]] - p).normalized();
                vertexNormal_[t[k]] += pmath::acos(std::clamp(e1.dot(e2), -1.0, 1.0)) * n;
                edgeNormal_.try_emplace(edgeKey(t[k], t[(k + 1) % 3]), Eigen::Vector3d::Zero())
                    .first->second += n;
            }
        }
    }

    double signedDistance(const Eigen::Vector3d& x, int triangle) const {
        const auto& t = mesh_.triangles[triangle];
        const TriangleClosestPoint c =
            closestPointAndFeature(x, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
        const Eigen::Vector3d& n = pseudonormal(t, triangle, c.feature);
        const Eigen::Vector3d offset = x - c.point;
        return offset.dot(n) >= 0.0 ? offset.norm() : -offset.norm();
    }

private:
    static std::uint64_t edgeKey(int a, int b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
               static_cast<std::uint32_t>(std::max(a, b));
    }
    Eigen::Vector3d triangleNormal(const std::array<int, 3>& t) const {
        const Eigen::Vector3d n =
            (mesh_.vertices[t[1]] - mesh_.vertices[t[0]]).cross(mesh_.vertices[t[2]] - mesh_.vertices[t[0]]);
        const double norm = n.norm();
        return norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d(Eigen::Vector3d::Zero());
    }
    const Eigen::Vector3d& pseudonormal(const std::array<int, 3>& t, int triangle, TriangleFeature f) const {
        switch (f) {
            case TriangleFeature::Face:
                return faceNormal_[triangle];
            case TriangleFeature::EdgeAB:
                return edgeNormal_.at(edgeKey(t[0], t[1]));
            case TriangleFeature::EdgeBC:
                return edgeNormal_.at(edgeKey(t[1], t[2]));
            case TriangleFeature::EdgeCA:
                return edgeNormal_.at(edgeKey(t[2], t[0]));
            case TriangleFeature::VertexA:
                return vertexNormal_[t[0]];
            case TriangleFeature::VertexB:
                return vertexNormal_[t[1]];
            case TriangleFeature::VertexC:
                return vertexNormal_[t[2]];
        }
        return faceNormal_[triangle];
    }

    const TriangleMesh& mesh_;
    std::vector<Eigen::Vector3d> faceNormal_;
    std::vector<Eigen::Vector3d> vertexNormal_;
    std::unordered_map<std::uint64_t, Eigen::Vector3d> edgeNormal_;
};

// Replaces the narrow-band values of `grid` by exact signed distances from each voxel's closest
// triangle. OpenVDB's meshToVolume signs some voxels that the surface passes through as outside
// (1.6 % of the bunny's and 6 % of the armadillo's voxels within one voxel of the surface), which
// shrinks the body by up to half a percent.
void exactNarrowBand(FloatGrid& grid, const Int32Grid& closestTriangle, const TriangleMesh& mesh) {
    using LeafT = FloatGrid::TreeType::LeafNodeType;
    const PseudonormalSign sign(mesh);
    const double dx = grid.voxelSize()[0];
    const float limit = 0.999f * kHalfWidthVoxels * static_cast<float>(dx);
    std::vector<LeafT*> leaves;
    grid.tree().getNodes(leaves);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const tbb::blocked_range<size_t>& r) {
        const Int32Grid::ConstAccessor triangleAcc = closestTriangle.getConstAccessor();
        for (size_t n = r.begin(); n != r.end(); ++n)
            for (auto it = leaves[n]->beginValueOn(); it; ++it) {
                const int t = triangleAcc.getValue(it.getCoord());
                if (t < 0) continue;
                const double d = sign.signedDistance(voxelCentre(it.getCoord(), dx), t);
                it.setValue(std::clamp(static_cast<float>(d), -limit, limit));
            }
    });
}

// Fraction of the unit cube [0,1]^3 where m . x <= alpha, for m >= 0 with m_x + m_y + m_z = 1
// (Scardovelli & Zaleski 2000, J. Comput. Phys. 164).
double cubeFractionBelowPlane(std::array<double, 3> m, double alpha) {
    if (alpha <= 0.0) return 0.0;
    if (alpha >= 1.0) return 1.0;
    std::sort(m.begin(), m.end());
    if (alpha > 0.5) return 1.0 - cubeFractionBelowPlane(m, 1.0 - alpha);
    const double m1 = m[0], m2 = m[1], m3 = m[2], m12 = m1 + m2;
    if (alpha < m1) return alpha * alpha * alpha / (6.0 * m1 * m2 * m3);
    if (alpha < m2) return alpha * (alpha - m1) / (2.0 * m2 * m3) + m1 * m1 / (6.0 * m2 * m3);
    if (alpha < std::min(m12, m3))
        return (alpha * alpha * (3.0 * m12 - alpha) + m1 * m1 * (m1 - 3.0 * alpha) +
                m2 * m2 * (m2 - 3.0 * alpha)) /
               (6.0 * m1 * m2 * m3);
    if (m12 <= m3) return (2.0 * alpha - m12) / (2.0 * m3);
    return (alpha * alpha * (3.0 - 2.0 * alpha) + m1 * m1 * (m1 - 3.0 * alpha) +
            m2 * m2 * (m2 - 3.0 * alpha) + m3 * m3 * (m3 - 3.0 * alpha)) /
           (6.0 * m1 * m2 * m3);
}

// Inside fraction of the voxel at ijk whose signed distance is phi (voxel units): the part of the
// voxel below the tangent plane of the distance field, exact for planar surfaces in any
// orientation. `normal` receives the outward unit normal (zero where the gradient is unusable:
// there a box filter of the distance is used).
double voxelInsideFraction(const FloatGrid::ConstAccessor& acc, const Coord& ijk, double voxelSize,
                           Eigen::Vector3d& normal) {
    normal.setZero();
    const double phi = acc.getValue(ijk) / voxelSize;
    if (phi >= kVoxelHalfDiagonal) return 0.0;  // the plane misses the voxel
    if (phi <= -kVoxelHalfDiagonal) return 1.0;
    const Eigen::Vector3d g(acc.getValue(ijk.offsetBy(1, 0, 0)) - acc.getValue(ijk.offsetBy(-1, 0, 0)),
                            acc.getValue(ijk.offsetBy(0, 1, 0)) - acc.getValue(ijk.offsetBy(0, -1, 0)),
                            acc.getValue(ijk.offsetBy(0, 0, 1)) - acc.getValue(ijk.offsetBy(0, 0, -1)));
    const double gradientNorm = g.norm() / (2.0 * voxelSize);           // 1 for an exact distance field
    if (!(gradientNorm > 0.5)) return std::clamp(0.5 - phi, 0.0, 1.0);  // medial axis or kink
    normal = g.normalized();
    std::array<double, 3> m = {std::abs(normal.x()), std::abs(normal.y()), std::abs(normal.z())};
    const double sum = m[0] + m[1] + m[2];
    for (double& c : m) {
        c /= sum;
        if (c < 1e-7) c = 0.0;  // the formula's grazing limits are exact with zeros
    }
    const double alpha = (-phi + 0.5 * sum) / sum;
    return cubeFractionBelowPlane(m, alpha);
}

struct Moments {
    double volume = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();   // about the reference point
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // integral of x x^T about the reference point

    void addBox(const Eigen::Vector3d& centre, const Eigen::Vector3d& size) {
        const double v = size.prod();
        volume += v;
        first += v * centre;
        second += v * (centre * centre.transpose());
        second.diagonal() += v / 12.0 * size.cwiseProduct(size);
    }
    void add(const Moments& o) {
        volume += o.volume;
        first += o.first;
        second += o.second;
    }
};

double trilinear(const FloatGrid::ConstAccessor& acc, const Eigen::Vector3d& p, double voxelSize) {
    const Eigen::Vector3d q = p / voxelSize;
    const Eigen::Vector3d f = q.array().floor();
    const Coord base(static_cast<int>(f.x()), static_cast<int>(f.y()), static_cast<int>(f.z()));
    const Eigen::Vector3d t = q - f;
    double value = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const int i = corner & 1, j = (corner >> 1) & 1, k = (corner >> 2) & 1;
        const double w = (i ? t.x() : 1.0 - t.x()) * (j ? t.y() : 1.0 - t.y()) * (k ? t.z() : 1.0 - t.z());
        value += w * acc.getValue(base.offsetBy(i, j, k));
    }
    return value;
}

Eigen::Vector3d trilinearGradient(const FloatGrid::ConstAccessor& acc, const Eigen::Vector3d& p,
                                  double voxelSize) {
    Eigen::Vector3d g;
    for (int axis = 0; axis < 3; ++axis) {
        Eigen::Vector3d h = Eigen::Vector3d::Zero();
        h[axis] = 0.5 * voxelSize;
        g[axis] = (trilinear(acc, p + h, voxelSize) - trilinear(acc, p - h, voxelSize)) / voxelSize;
    }
    return g;
}

// Mean curvature (k1 + k2) / 2 of the level sets of phi at voxel ijk, central differences.
double voxelMeanCurvature(const FloatGrid::ConstAccessor& acc, const Coord& ijk, double voxelSize) {
    auto f = [&](int i, int j, int k) { return static_cast<double>(acc.getValue(ijk.offsetBy(i, j, k))); };
    const double c = f(0, 0, 0);
    const double h = voxelSize;
    const double px = (f(1, 0, 0) - f(-1, 0, 0)) / (2 * h);
    const double py = (f(0, 1, 0) - f(0, -1, 0)) / (2 * h);
    const double pz = (f(0, 0, 1) - f(0, 0, -1)) / (2 * h);
    const double pxx = (f(1, 0, 0) - 2 * c + f(-1, 0, 0)) / (h * h);
    const double pyy = (f(0, 1, 0) - 2 * c + f(0, -1, 0)) / (h * h);
    const double pzz = (f(0, 0, 1) - 2 * c + f(0, 0, -1)) / (h * h);
    const double pxy = (f(1, 1, 0) - f(1, -1, 0) - f(-1, 1, 0) + f(-1, -1, 0)) / (4 * h * h);
    const double pxz = (f(1, 0, 1) - f(1, 0, -1) - f(-1, 0, 1) + f(-1, 0, -1)) / (4 * h * h);
    const double pyz = (f(0, 1, 1) - f(0, 1, -1) - f(0, -1, 1) + f(0, -1, -1)) / (4 * h * h);
    const double g2 = px * px + py * py + pz * pz;
    if (g2 < 1e-12) return 0.0;
    const double numerator = pxx * (py * py + pz * pz) + pyy * (px * px + pz * pz) +
                             pzz * (px * px + py * py) -
                             2.0 * (px * py * pxy + px * pz * pxz + py * pz * pyz);
    return numerator / (2.0 * g2 * std::sqrt(g2));
}

void requireFinitePoint(const Eigen::Vector3d& p, const std::string& body, const char* query) {
    if (!p.allFinite()) throw Error(body + ": " + query + " needs a finite point, got " + describePoint(p));
}

}  // namespace

FloatGrid::Ptr makeLevelSet(double voxelSize) {
    initializeOpenVdbOnce();
    FloatGrid::Ptr grid = FloatGrid::create(static_cast<float>(kHalfWidthVoxels * voxelSize));
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    return grid;
}

MassProperties integrateMass(const FloatGrid& phi) {
    using LeafT = FloatGrid::TreeType::LeafNodeType;
    const double dx = phi.voxelSize()[0];
    const auto& tree = phi.tree();

    std::vector<const LeafT*> leaves;
    tree.getNodes(leaves);
    openvdb::CoordBBox bounds;
    tree.evalLeafBoundingBox(bounds);
    // Moments about the middle of the grid keep the sums well conditioned.
    const Eigen::Vector3d reference =
        bounds.empty()
            ? Eigen::Vector3d(Eigen::Vector3d::Zero())
            : Eigen::Vector3d(0.5 * (voxelCentre(bounds.min(), dx) + voxelCentre(bounds.max(), dx)));

    // One partial sum per leaf, added in leaf order: the result does not depend on threads.
    // A partial voxel's centroid is moved from its centre against the normal by (1 - f) / 2
    // voxel (exact for axis-aligned planes).
    std::vector<Moments> perLeaf(leaves.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const tbb::blocked_range<size_t>& r) {
        const FloatGrid::ConstAccessor acc = phi.getConstAccessor();
        Eigen::Vector3d normal;
        for (size_t n = r.begin(); n != r.end(); ++n) {
            double count = 0.0;
            Eigen::Vector3d first = Eigen::Vector3d::Zero();
            Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
            for (auto it = leaves[n]->cbeginValueAll(); it; ++it) {
                const float value = *it;
                double f;
                if (value >= static_cast<float>(kVoxelHalfDiagonal * dx)) continue;
                if (value <= static_cast<float>(-kVoxelHalfDiagonal * dx)) {
                    f = 1.0;
                    normal.setZero();
                } else {
                    f = voxelInsideFraction(acc, it.getCoord(), dx, normal);
                    if (f == 0.0) continue;
                }
                const Eigen::Vector3d x =
                    voxelCentre(it.getCoord(), dx) - reference - (0.5 * (1.0 - f) * dx) * normal;
                count += f;
                first += f * x;
                second += f * (x * x.transpose());
                second.diagonal().array() += f * dx * dx / 12.0;
            }
            const double cell = dx * dx * dx;
            perLeaf[n].volume = count * cell;
            perLeaf[n].first = first * cell;
            perLeaf[n].second = second * cell;
        }
    });
    Moments total;
    for (const Moments& m : perLeaf) total.add(m);

    // Interior tiles above the leaf level.
    auto tile = tree.cbeginValueAll();
    tile.setMaxDepth(decltype(tile)::LEAF_DEPTH - 1);
    for (; tile; ++tile) {
        if (!(*tile < 0.0f)) continue;
        const openvdb::CoordBBox box = tile.getBoundingBox();
        const Eigen::Vector3d lo = voxelCentre(box.min(), dx) - Eigen::Vector3d::Constant(0.5 * dx);
        const Eigen::Vector3d hi = voxelCentre(box.max(), dx) + Eigen::Vector3d::Constant(0.5 * dx);
        total.addBox(0.5 * (lo + hi) - reference, hi - lo);
    }

    MassProperties p;
    p.volume = total.volume;
    if (total.volume <= 0.0) return p;
    const Eigen::Vector3d offset = total.first / total.volume;
    p.centreOfMass = reference + offset;
    const Eigen::Matrix3d central = total.second - total.volume * offset * offset.transpose();
    p.inertiaPerDensity = central.trace() * Eigen::Matrix3d::Identity() - central;
    return p;
}

TriangleMesh meshFromGrid(const FloatGrid& phi, const std::string& name, double adaptivity, double isovalue) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    serially([&] { openvdb::tools::volumeToMesh(phi, points, triangles, quads, isovalue, adaptivity); });

    TriangleMesh mesh;
    mesh.name = name;
    auto point = [&](unsigned i) { return Eigen::Vector3d(points[i][0], points[i][1], points[i][2]); };
    auto addTriangle = [&](unsigned a, unsigned b, unsigned c) {
        if (a == b || b == c || a == c) return;
        mesh.triangles.push_back({static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)});
    };
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    for (const auto& t : triangles) addTriangle(t[0], t[1], t[2]);
    for (const auto& q : quads) {
        // Split along the shorter diagonal: better shaped triangles.
        if ((point(q[0]) - point(q[2])).squaredNorm() <= (point(q[1]) - point(q[3])).squaredNorm()) {
            addTriangle(q[0], q[1], q[2]);
            addTriangle(q[0], q[2], q[3]);
        } else {
            addTriangle(q[0], q[1], q[3]);
            addTriangle(q[1], q[2], q[3]);
        }
    }
    takeUsedVertices(mesh, points.size(), [&](int v) { return point(static_cast<unsigned>(v)); });
    // OpenVDB's winding is inward for level sets; make the normals point outward.
    double signedVolume = 0.0;
    for (const auto& t : mesh.triangles)
        signedVolume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    if (signedVolume < 0.0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

TriangleMesh collisionMeshFromGrid(const FloatGrid& phi, int targetTriangles, const std::string& name,
                                   const TriangleMesh* fineMesh) {
    // Decimating OpenVDB's adaptive mesh (10x fewer triangles) is 20x faster than decimating the
    // fine one. The adaptive mesh may hold a few self-intersecting pairs; they almost always
    // collapse away, and if not (or if it is not closed and manifold) the fine mesh is used.
    constexpr double kAdaptivity = 0.1;
    const TriangleMesh adaptive = meshFromGrid(phi, name, kAdaptivity);
    if (static_cast<int>(adaptive.triangles.size()) > 2 * targetTriangles &&
        inspectMesh(adaptive).isClosedManifold()) {
        TriangleMesh coarse = decimateMesh(adaptive, targetTriangles);
        if (inspectMesh(coarse).isClosedSolid()) return coarse;
        logf(LogLevel::Debug, name,
             ": decimated adaptive mesh self-intersects; decimating the fine mesh instead");
    }
    return decimateMesh(fineMesh ? *fineMesh : meshFromGrid(phi, name), targetTriangles);
}

}  // namespace levelset

using namespace levelset;

void levelset::carveSlab(FloatGrid& object, const FloatGrid& solid, const FloatGrid& slab) {
    const float background = solid.background();
    auto solidAcc = solid.getConstAccessor();
    auto objectAcc = object.getAccessor();
    for (auto it = slab.cbeginValueOn(); it; ++it) {
        const Coord ijk = it.getCoord();
        if (!(solidAcc.getValue(ijk) < background)) continue;
        const float carved = -*it;
        if (carved > objectAcc.getValue(ijk)) objectAcc.setValueOn(ijk, std::min(carved, background));
    }
}

void LevelSetBody::Impl::rebuildObject() {
    openvdb::CoordBBox box = solid->evalActiveVoxelBoundingBox();
    boundingDiagonal =
        box.empty() ? 0.0 : (voxelCentre(box.max(), voxelSize) - voxelCentre(box.min(), voxelSize)).norm();
    object = solid->deepCopy();
    if (crack) carveSlab(*object, *solid, *crack);
}

LevelSetBody::DefaultVoxel LevelSetBody::defaultVoxel(const TriangleMesh& mesh) {
    if (mesh.vertices.empty())
        throw Error((mesh.name.empty() ? "<unnamed mesh>" : mesh.name) + ": mesh has no vertices");
    Eigen::Vector3d lo = mesh.vertices.front(), hi = mesh.vertices.front();
    for (const auto& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    DefaultVoxel d;
    d.byLength = (hi - lo).maxCoeff() / kDefaultVoxelsAcross;
    const double area = surfaceArea(mesh);
    d.thickness = area > 0.0 ? 2.0 * std::abs(enclosedVolume(mesh)) / area : 0.0;
    d.byThickness = d.thickness / kDefaultVoxelsThrough;
    const double finest = d.byLength * kDefaultVoxelsAcross / kDefaultMaxVoxelsAcross;
    d.size = d.byThickness > 0.0 && d.byThickness < d.byLength ? std::max(d.byThickness, finest) : d.byLength;
    return d;
}

double LevelSetBody::defaultVoxelSize(const TriangleMesh& mesh) {
    return defaultVoxel(mesh).size;
}

LevelSetBody::LevelSetBody(const TriangleMesh& closedMesh, double voxelSize)
    : impl_(std::make_unique<Impl>()) {
    TriangleMesh mesh = closedMesh;
    const std::string source = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (!std::isfinite(voxelSize) || voxelSize <= 0.0) {
        std::ostringstream msg;
        msg << source << ": level-set voxel size must be finite and > 0 m, got " << voxelSize;
        throw Error(msg.str());
    }
    requireClosedSolid(mesh);
    Eigen::Vector3d lo = mesh.vertices.front(), hi = mesh.vertices.front();
    for (const auto& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double across = (hi - lo).maxCoeff() / voxelSize;
    if (across > kMaxVoxelsAcross) {
        std::ostringstream msg;
        msg << source << ": voxel size " << voxelSize << " m gives " << across
            << " voxels across the longest side; the limit is " << kMaxVoxelsAcross;
        throw Error(msg.str());
    }
    if (across < 4.0)
        logf(LogLevel::Warning, source, ": voxel size ", voxelSize, " m gives only ", across,
             " voxels across; the level set cannot resolve this body");

    Impl& b = *impl_;
    b.name = source;
    b.voxelSize = voxelSize;
    FloatGrid::Ptr grid = makeLevelSet(voxelSize);
    const IndexSpaceTriangles adapter{mesh.vertices, mesh.triangles, 1.0 / voxelSize};
    // The mesh is free of self-intersections (checked above), so OpenVDB's renormalization,
    // which smooths bumps from overlapping parts, would only bias the field (it costs 0.7 % of
    // the armadillo's volume and 4 % of a sphere's curvature).
    Int32Grid::Ptr closest = Int32Grid::create(-1);
    b.solid = serially([&] {
        return openvdb::tools::meshToVolume<FloatGrid>(
            adapter, grid->transform(), kHalfWidthVoxels, kHalfWidthVoxels,
            openvdb::tools::DISABLE_RENORMALIZATION, closest.get());
    });
    exactNarrowBand(*b.solid, *closest, mesh);
    b.solid->setGridClass(openvdb::GRID_LEVEL_SET);
    b.crack = makeLevelSet(voxelSize);
    b.crackTriangle = Int32Grid::create(-1);
    b.crackTriangle->setTransform(b.solid->transformPtr());
    b.mass = integrateMass(*b.solid);
    b.rebuildObject();
    b.originalVolume = b.mass.volume;
    if (!(b.mass.volume > 0.0))
        throw Error(source + ": the level set of the mesh encloses no voxel; use a smaller voxel size");
}

LevelSetBody::LevelSetBody(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LevelSetBody::~LevelSetBody() = default;
LevelSetBody::LevelSetBody(LevelSetBody&&) noexcept = default;
LevelSetBody& LevelSetBody::operator=(LevelSetBody&&) noexcept = default;

const std::string& LevelSetBody::name() const {
    return impl_->name;
}
double LevelSetBody::voxelSize() const {
    return impl_->voxelSize;
}
double LevelSetBody::originalVolume() const {
    return impl_->originalVolume;
}
const MassProperties& LevelSetBody::massProperties() const {
    return impl_->mass;
}

double LevelSetBody::signedDistance(const Eigen::Vector3d& p) const {
    requireFinitePoint(p, impl_->name, "signedDistance");
    return trilinear(impl_->object->getConstAccessor(), p, impl_->voxelSize);
}

bool LevelSetBody::isInsideObject(const Eigen::Vector3d& p) const {
    return signedDistance(p) < 0.0;
}

bool LevelSetBody::isInsideSolid(const Eigen::Vector3d& p) const {
    requireFinitePoint(p, impl_->name, "isInsideSolid");
    return trilinear(impl_->solid->getConstAccessor(), p, impl_->voxelSize) < 0.0;
}

Eigen::Vector3d LevelSetBody::solidNormal(const Eigen::Vector3d& p) const {
    requireFinitePoint(p, impl_->name, "solidNormal");
    const Eigen::Vector3d g = trilinearGradient(impl_->solid->getConstAccessor(), p, impl_->voxelSize);
    return g.norm() > 0.0 ? Eigen::Vector3d(g.normalized()) : Eigen::Vector3d::Zero();
}

bool LevelSetBody::isInsideCrack(const Eigen::Vector3d& p) const {
    return crackAt(p) >= 0;
}

int LevelSetBody::crackAt(const Eigen::Vector3d& p) const {
    requireFinitePoint(p, impl_->name, "crackAt");
    const Impl& b = *impl_;
    if (b.crackTriangles.empty()) return -1;
    if (!(trilinear(b.crack->getConstAccessor(), p, b.voxelSize) < 0.0)) return -1;
    const int t = b.crackTriangle->getConstAccessor().getValue(nearestVoxel(p, b.voxelSize));
    return t >= 0 ? b.crackTriangles[t].crackId : -1;
}

std::vector<int> LevelSetBody::crackIds() const {
    std::set<int> ids;
    for (const auto& t : impl_->crackTriangles) ids.insert(t.crackId);
    return {ids.begin(), ids.end()};
}

void LevelSetBody::renameCracks(const std::map<int, int>& newIdOf) {
    for (const int id : crackIds())
        if (newIdOf.count(id) == 0)
            throw Error(impl_->name + ": renameCracks has no new id for crack " + std::to_string(id));
    for (auto& t : impl_->crackTriangles) t.crackId = newIdOf.at(t.crackId);
}

double LevelSetBody::meanCurvature(const Eigen::Vector3d& p) const {
    requireFinitePoint(p, impl_->name, "meanCurvature");
    const Impl& b = *impl_;
    const double dx = b.voxelSize;
    const auto acc = b.object->getConstAccessor();

    // Project onto the zero level set (Newton steps along the gradient).
    Eigen::Vector3d q = p;
    for (int iteration = 0; iteration < 8; ++iteration) {
        const double phi = trilinear(acc, q, dx);
        if (std::abs(phi) >= kHalfWidthVoxels * dx * 0.999)
            throw Error(b.name + ": meanCurvature: point " + describePoint(p) +
                        " is not within 3 voxels of the body's surface");
        const Eigen::Vector3d g = trilinearGradient(acc, q, dx);
        if (g.squaredNorm() < 1e-12) break;
        q -= phi * g / g.squaredNorm();
        if (std::abs(phi) < 1e-4 * dx) break;
    }

    // Hat-weighted average over surface voxels within 2 voxels.
    const double radius = 2.0;
    const Coord centre = nearestVoxel(q, dx);
    double sum = 0.0, weights = 0.0;
    for (int i = -2; i <= 2; ++i)
        for (int j = -2; j <= 2; ++j)
            for (int k = -2; k <= 2; ++k) {
                const Coord ijk = centre.offsetBy(i, j, k);
                const double d = (voxelCentre(ijk, dx) - q).norm() / dx;
                if (d > radius) continue;
                if (std::abs(acc.getValue(ijk)) > dx) continue;
                const double w = 1.0 - d / (radius + 0.5);
                sum += w * voxelMeanCurvature(acc, ijk, dx);
                weights += w;
            }
    if (weights == 0.0) throw Error(b.name + ": meanCurvature: no surface voxel near " + describePoint(p));
    const double h = sum / weights;
    return std::abs(h) * 10.0 * b.boundingDiagonal < 1.0 ? 0.0 : h;
}

TriangleMesh LevelSetBody::visualMesh() const {
    return meshFromGrid(*impl_->object, impl_->name + " (visual)");
}

TriangleMesh LevelSetBody::collisionMesh(int targetTriangles) const {
    return collisionMeshFromGrid(*impl_->solid, targetTriangles, impl_->name + " (collision)", nullptr);
}

// Closed pieces of a BEM source below this fraction of the largest one's volume are debris of the
// coarse level set (MeshDebris.h).
constexpr double kDebrisVolumeFraction = 0.01;

TriangleMesh LevelSetBody::bemSourceMesh(int targetTriangles, double voxelsPerEdge) const {
    const Impl& b = *impl_;
    const std::string name = b.name + " (BEM source)";
    if (targetTriangles < 4)
        throw Error(name + ": BEM target of " + std::to_string(targetTriangles) + " triangles; need >= 4");
    if (!std::isfinite(voxelsPerEdge) || voxelsPerEdge <= 0.0)
        throw Error(name + ": voxels per BEM edge must be finite and > 0, got " +
                    std::to_string(voxelsPerEdge));
    const TriangleMesh fine = meshFromGrid(*b.solid, name);
    const double edge = std::sqrt(4.0 * surfaceArea(fine) / (std::sqrt(3.0) * targetTriangles));
    // At least two body voxels: at the body's own resolution the crack-rim wedges would stay.
    const double dx = std::max(edge / voxelsPerEdge, 2.0 * b.voxelSize);
    if (dx > edge / voxelsPerEdge)
        logf(LogLevel::Debug, name, ": BEM edge ", edge, " m is within ", 2.0 * voxelsPerEdge,
             " body voxels; its source is rebuilt at two body voxels, ", edge / dx, " per edge");
    // Mesh -> level set at the coarse voxel size (OpenVDB signs it by flood fill and
    // renormalises, so a fine mesh that touches itself at a wedge is no problem) -> mesh.
    FloatGrid::Ptr grid = makeLevelSet(dx);
    const IndexSpaceTriangles adapter{fine.vertices, fine.triangles, 1.0 / dx};
    FloatGrid::Ptr coarse = serially([&] {
        return openvdb::tools::meshToVolume<FloatGrid>(adapter, grid->transform(), kHalfWidthVoxels,
                                                       kHalfWidthVoxels);
    });
    coarse->setGridClass(openvdb::GRID_LEVEL_SET);
    TriangleMesh mesh = meshFromGrid(*coarse, name);
    // The coarse surface cuts convex parts short (by ~3 % of a piece's volume at 3 voxels per
    // edge): offset it by the volume deficit spread over its area, at most half a coarse voxel.
    const double volume = enclosedVolume(mesh);
    const double coarseArea = surfaceArea(mesh);
    if (!(coarseArea > 0.0)) return mesh;  // nothing left at this resolution; the caller reports it
    const double wanted = (b.mass.volume - volume) / coarseArea;
    const double offset = std::clamp(wanted, -0.5 * dx, 0.5 * dx);
    if (offset != wanted)
        logf(LogLevel::Info, name, ": volume offset ", wanted, " m limited to half a coarse voxel (", offset,
             " m); the BEM source keeps ", 100.0 * (volume + offset * coarseArea) / b.mass.volume,
             " % of the volume");
    TriangleMesh shifted = meshFromGrid(*coarse, name, 0.0, offset);
    TriangleMesh& source = shifted.triangles.size() >= 4 ? shifted : mesh;
    const DroppedDebris debris = dropDebris(source, kDebrisVolumeFraction);
    if (debris.pieces > 0)
        logf(LogLevel::Info, name, ": ", debris.pieces, " closed pieces below ",
             100.0 * kDebrisVolumeFraction, " % of the largest one's volume left out (", debris.volume,
             " m^3 in all)");
    return source;
}

void LevelSetBody::writeVdb(const std::string& path) const {
    const Impl& b = *impl_;
    levelset::FloatGrid::Ptr object = b.object->deepCopy();
    object->setName(b.name + ".object");
    object->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::GridPtrVec grids{object};
    if (b.crack) {
        levelset::FloatGrid::Ptr crack = b.crack->deepCopy();
        crack->setName(b.name + ".cracks");
        crack->setGridClass(openvdb::GRID_LEVEL_SET);
        grids.push_back(crack);
    }
    try {
        openvdb::io::File file(path);
        file.write(grids);
        file.close();
    } catch (const std::exception& e) {
        throw Error("cannot write level set of " + b.name + " to '" + path + "': " + e.what());
    }
}

void LevelSetBody::cutAlongSurface(const TriangleMesh& sheet, int crackId) {
    Impl& b = *impl_;
    const std::string source =
        (sheet.name.empty() ? std::string("<unnamed crack sheet>") : sheet.name) + " on " + b.name;
    if (crackId < 0) throw Error(source + ": crack id must be >= 0, got " + std::to_string(crackId));
    if (sheet.triangles.empty()) throw Error(source + ": crack sheet has no triangles");
    const int nv = static_cast<int>(sheet.vertices.size());
    for (const auto& v : sheet.vertices)
        if (!v.allFinite()) throw Error(source + ": crack sheet has a non-finite vertex " + describePoint(v));
    for (const auto& t : sheet.triangles)
        for (int i : t)
            if (i < 0 || i >= nv)
                throw Error(source + ": crack sheet triangle index " + std::to_string(i) +
                            " is outside [0, " + std::to_string(nv) + ")");

    const double dx = b.voxelSize;
    const double background = kHalfWidthVoxels * dx;
    const double halfThickness = kCrackHalfThicknessVoxels * dx;

    // Only the parts of the sheet inside the solid's narrow band can cut anything.
    const openvdb::CoordBBox box = b.solid->evalActiveVoxelBoundingBox();
    const TriangleMesh kept =
        clipToBox(sheet, voxelCentre(box.min(), dx) - Eigen::Vector3d::Constant(background),
                  voxelCentre(box.max(), dx) + Eigen::Vector3d::Constant(background));
    if (kept.triangles.empty()) {
        logf(LogLevel::Info, source, ": crack sheet misses the body; nothing cut");
        return;
    }

    // Unsigned distance to the sheet out to where the slab's narrow band ends.
    Int32Grid::Ptr nearest = Int32Grid::create(-1);
    const IndexSpaceTriangles adapter{kept.vertices, kept.triangles, 1.0 / dx};
    const float band = static_cast<float>(kHalfWidthVoxels + kCrackHalfThicknessVoxels + 1.0);
    FloatGrid::Ptr distance = serially([&] {
        return openvdb::tools::meshToVolume<FloatGrid>(adapter, b.solid->transform(), band, band,
                                                       openvdb::tools::UNSIGNED_DISTANCE_FIELD,
                                                       nearest.get());
    });

    const int base = static_cast<int>(b.crackTriangles.size());
    for (const auto& t : kept.triangles)
        b.crackTriangles.push_back({kept.vertices[t[0]], kept.vertices[t[1]], kept.vertices[t[2]], crackId});

    // Slab level set (distance - half thickness), limited to the solid's narrow band and inside.
    FloatGrid::Ptr slab = makeLevelSet(dx);
    auto solidAcc = b.solid->getConstAccessor();
    auto nearestAcc = nearest->getConstAccessor();
    auto slabAcc = slab->getAccessor();
    auto crackAcc = b.crack->getAccessor();
    auto triangleAcc = b.crackTriangle->getAccessor();
    size_t slabVoxels = 0;
    for (auto it = distance->cbeginValueOn(); it; ++it) {
        const Coord ijk = it.getCoord();
        if (!(solidAcc.getValue(ijk) < background)) continue;
        const double value = *it - halfThickness;
        if (!(value < background)) continue;
        slabAcc.setValueOn(ijk, static_cast<float>(value));
        if (value < 0.0) ++slabVoxels;
        if (value < crackAcc.getValue(ijk)) {
            crackAcc.setValueOn(ijk, static_cast<float>(value));
            triangleAcc.setValueOn(ijk, base + nearestAcc.getValue(ijk));
        }
    }
    carveSlab(*b.object, *b.solid, *slab);
    logf(LogLevel::Debug, source, ": crack ", crackId, " cut with ", kept.triangles.size(), " triangles, ",
         slabVoxels, " slab voxels");
}

}  // namespace btfracture
