// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/RemeshEdits.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/geometry/MeshQuality.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace btfracture {

Eigen::Vector3d projectOntoSurface(const ClosestPointTree& surface, const Eigen::Vector3d& p,
                                   const Eigen::Vector3d& normal) {
    return surface.closestPoint(p, normal, 0.0).point;
}

Eigen::Vector3d edgeMidpointOnSurface(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int h) {
    const Eigen::Vector3d normal = mesh.faceAreaNormal(HalfEdgeMesh::face(h)).normalized() +
                                   mesh.faceAreaNormal(HalfEdgeMesh::face(mesh.twin(h))).normalized();
    return projectOntoSurface(surface, 0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h))),
                              normal);
}

CollapsePlan planCollapse(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int h,
                          const CollapseLimits& limits, CollapseGoal goal) {
    CollapsePlan plan;
    const int a = mesh.origin(h), b = mesh.target(h);
    // The merged vertex gets valence(a) + valence(b) - 4. Capping it keeps fans (and the cost of
    // the manifold test, quadratic in valence) bounded: on level-set fragment surfaces unbounded
    // merging grew fans of thousands of edges and stalled the remesher for minutes.
    if (mesh.valence(a) + mesh.valence(b) - 4 > kMaxCollapsedValence) return plan;
    if (!mesh.collapseKeepsManifold(h)) return plan;
    const Eigen::Vector3d normal = mesh.vertexNormal(a) + mesh.vertexNormal(b);
    const Eigen::Vector3d candidates[3] = {
        projectOntoSurface(surface, 0.5 * (mesh.position(a) + mesh.position(b)), normal), mesh.position(a),
        mesh.position(b)};
    for (const Eigen::Vector3d& p : candidates) {
        const HalfEdgeMesh::EditPreview preview = mesh.previewCollapse(h, p);
        if (preview.maxEdgeLength >= limits.maxEdgeLength ||
            preview.minNormalCosine < limits.minNormalCosine || preview.deviation > limits.maxDeviation)
            continue;
        const bool better = goal == CollapseGoal::KeepShape ? preview.deviation < plan.deviation
                                                            : preview.minAngle > plan.minAngle;
        if (!plan.valid || better) {
            plan.valid = true;
            plan.position = p;
            plan.minAngle = preview.minAngle;
            plan.deviation = preview.deviation;
        }
    }
    return plan;
}

double moveDeviation(const HalfEdgeMesh& mesh, int v, const Eigen::Vector3d& q) {
    const Eigen::Vector3d& p = mesh.position(v);
    double nearest2 = std::numeric_limits<double>::infinity();
    mesh.forEachOutgoing(v, [&](int g) {
        const Eigen::Vector3d c =
            closestPointOnTriangle(p, q, mesh.position(mesh.target(g)), mesh.position(mesh.apex(g)));
        nearest2 = std::min(nearest2, (c - p).squaredNorm());
    });
    return std::sqrt(nearest2);
}

VertexMove optimizeVertexAngles(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int v, double step,
                                double minNormalCosine) {
    // Smallest angle around v if it moved to q; -infinity if a face would turn too far.
    auto score = [&](const Eigen::Vector3d& q) {
        double smallest = M_PI;
        bool turned = false;
        mesh.forEachOutgoing(v, [&](int g) {
            const Eigen::Vector3d& u = mesh.position(mesh.target(g));
            const Eigen::Vector3d& w = mesh.position(mesh.apex(g));
            const Eigen::Vector3d n = (u - q).cross(w - q);
            const Eigen::Vector3d old = mesh.faceAreaNormal(HalfEdgeMesh::face(g));
            const double lengths = n.norm() * old.norm();
            if (!(lengths > 0.0) || n.dot(old) < minNormalCosine * lengths) turned = true;
            smallest = std::min(smallest, triangleMinAngle(q, u, w));
        });
        return turned ? -std::numeric_limits<double>::infinity() : smallest;
    };

    const Eigen::Vector3d normal = mesh.vertexNormal(v);
    Eigen::Vector3d t1 = normal.unitOrthogonal();
    Eigen::Vector3d t2 = normal.cross(t1);
    VertexMove move;
    move.position = mesh.position(v);
    move.minAngle = score(move.position);
    const double start = move.minAngle;

    // First trial: the projected centroid of the neighbours.
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    int neighbours = 0;
    mesh.forEachOutgoing(v, [&](int g) {
        centroid += mesh.position(mesh.target(g));
        ++neighbours;
    });
    const Eigen::Vector3d c = projectOntoSurface(surface, centroid / neighbours, normal);
    if (const double s = score(c); s > move.minAngle) {
        move.position = c;
        move.minAngle = s;
    }

    constexpr int directions = 8;
    constexpr int maxEvaluations = 200;
    int evaluations = 0;
    for (double h = step; h > 0.01 * step && evaluations < maxEvaluations;) {
        bool moved = false;
        for (int k = 0; k < directions; ++k) {
            const double phi = 2.0 * M_PI * k / directions;
            const Eigen::Vector3d trial = projectOntoSurface(
                surface, move.position + h * (pmath::cos(phi) * t1 + pmath::sin(phi) * t2), normal);
            ++evaluations;
            if (const double s = score(trial); s > move.minAngle + 1e-9) {
                move.position = trial;
                move.minAngle = s;
                moved = true;
            }
        }
        if (!moved) h *= 0.5;
    }
    move.improved = move.minAngle > start + 1e-9;
    return move;
}

}  // namespace btfracture
