// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/SurfaceFit.h>

#include <btFracture/core/SelfIntersection.h>
#include <btFracture/geometry/MeshQuality.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace btfracture {
namespace {

constexpr int kRounds = 3;                // offset updates (each one removes most of the remaining error)
constexpr double kMinNormalCosine = 0.5;  // a face may turn by at most 60 degrees

// Mean signed distance of face f from the surface (positive outside), by the edge-midpoint rule.
double meanSignedDistance(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int f) {
    const auto tri = mesh.faceVertices(f);
    const Eigen::Vector3d normal = mesh.faceAreaNormal(f);
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d x = 0.5 * (mesh.position(tri[k]) + mesh.position(tri[(k + 1) % 3]));
        const ClosestPointTree::Hit hit = surface.closestPoint(x, normal, 0.0);
        sum += (x - hit.point).dot(surface.triangleNormal(hit.triangle));
    }
    return sum / 3.0;
}

}  // namespace

SurfaceFitResult fitAcrossSurface(HalfEdgeMesh& mesh, const ClosestPointTree& surface, double minAngle,
                                  double maxOffset) {
    SurfaceFitResult result;
    const int nv = mesh.vertexSlots(), nf = mesh.faceSlots();
    std::vector<Eigen::Vector3d> original(nv), normal(nv);
    for (int v = 0; v < nv; ++v)
        if (mesh.vertexAlive(v)) {
            original[v] = mesh.position(v);
            normal[v] = mesh.vertexNormal(v);
        }
    std::vector<double> faceMinAngle(nf, 0.0);
    std::vector<Eigen::Vector3d> faceNormal(nf);
    for (int f = 0; f < nf; ++f)
        if (mesh.faceAlive(f)) {
            faceMinAngle[f] = mesh.faceMinAngle(f);
            faceNormal[f] = mesh.faceAreaNormal(f);
        }

    std::vector<double> offset(nv, 0.0), faceError(nf, 0.0);
    for (int round = 0; round < kRounds; ++round) {
        for (int f = 0; f < nf; ++f)
            if (mesh.faceAlive(f)) faceError[f] = meanSignedDistance(mesh, surface, f);
        for (int v = 0; v < nv; ++v) {
            if (!mesh.vertexAlive(v)) continue;
            double weighted = 0.0, area = 0.0;
            mesh.forEachOutgoing(v, [&](int h) {
                const int f = HalfEdgeMesh::face(h);
                const double a = faceNormal[f].norm();
                weighted += a * faceError[f];
                area += a;
            });
            if (area > 0.0) offset[v] -= weighted / area;
        }
        for (int v = 0; v < nv; ++v)
            if (mesh.vertexAlive(v))
                mesh.setPosition(v, original[v] + std::clamp(offset[v], -maxOffset, maxOffset) * normal[v]);
    }
    for (int v = 0; v < nv; ++v)
        if (mesh.vertexAlive(v)) {
            if (std::abs(offset[v]) > maxOffset) ++result.limitedVertices;
            result.largestOffset = std::max(result.largestOffset, std::min(std::abs(offset[v]), maxOffset));
        }

    // Put back the vertices of faces that got worse than allowed, until none is left.
    auto acceptable = [&](int f) {
        const Eigen::Vector3d n = mesh.faceAreaNormal(f);
        const double angle = mesh.faceMinAngle(f);
        return n.dot(faceNormal[f]) >= kMinNormalCosine * n.norm() * faceNormal[f].norm() &&
               (angle >= minAngle || angle >= faceMinAngle[f]);
    };
    std::vector<char> kept(nv, 0);
    auto keep = [&](int f) {
        bool changed = false;
        for (int v : mesh.faceVertices(f))
            if (!kept[v]) {
                kept[v] = 1;
                mesh.setPosition(v, original[v]);
                ++result.keptVertices;
                changed = true;
            }
        return changed;
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (int f = 0; f < nf; ++f)
            if (mesh.faceAlive(f) && !acceptable(f)) changed = keep(f) || changed;
    }
    // Likewise for faces that the offsets made intersect others (in narrow gaps).
    std::vector<int> faceOfTriangle;
    for (int f = 0; f < nf; ++f)
        if (mesh.faceAlive(f)) faceOfTriangle.push_back(f);
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [a, b] : findSelfIntersections(mesh.toTriangleMesh("")))
            for (int t : {a, b}) changed = keep(faceOfTriangle[t]) || changed;
    }
    return result;
}

}  // namespace btfracture
