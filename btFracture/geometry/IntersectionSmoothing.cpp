// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/IntersectionSmoothing.h>

#include <btFracture/core/SelfIntersection.h>
#include <btFracture/geometry/MeshQuality.h>
#include <btFracture/geometry/RemeshEdits.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace btfracture {
namespace {

constexpr double kMinNormalCosine = 0.5;  // a smoothed face may turn by at most 60 degrees
// Flips and collapses are judged by the intersections they leave, so they may turn faces more.
constexpr double kEditMinNormalCosine = 0.0;
constexpr std::size_t kEditPairs = 4;  // flips and collapses are tried on this many pairs per round
constexpr int kMaxRings = 2;           // smooth at most this many rings around the intersections

// Moves v towards the centroid of its neighbours (half way, else a quarter of the way) if the
// faces around it stay acceptable.
bool smoothVertex(HalfEdgeMesh& mesh, int v, double minAngle) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    int neighbours = 0;
    mesh.forEachOutgoing(v, [&](int h) {
        centroid += mesh.position(mesh.target(h));
        ++neighbours;
    });
    const double floor = std::min(minAngle, mesh.minAngleAroundVertex(v));
    for (double step : {0.5, 0.25}) {
        const Eigen::Vector3d q = mesh.position(v) + step * (centroid / neighbours - mesh.position(v));
        bool acceptable = true;
        mesh.forEachOutgoing(v, [&](int h) {
            const Eigen::Vector3d& u = mesh.position(mesh.target(h));
            const Eigen::Vector3d& w = mesh.position(mesh.apex(h));
            const Eigen::Vector3d n = (u - q).cross(w - q), old = mesh.faceAreaNormal(HalfEdgeMesh::face(h));
            if (n.dot(old) < kMinNormalCosine * n.norm() * old.norm() || triangleMinAngle(q, u, w) < floor)
                acceptable = false;
        });
        if (acceptable) {
            mesh.setPosition(v, q);
            return true;
        }
    }
    return false;
}

int countIntersections(const HalfEdgeMesh& mesh) {
    return static_cast<int>(findSelfIntersections(mesh.toTriangleMesh("")).size());
}

// The flip or collapse of an edge of the given faces that leaves the fewest intersecting pairs,
// if that is fewer than `pairs`; failing that, the collapse that leaves as many pairs with the
// largest angles (it removes a vertex from a region too coarse for its shape, such as a finger
// thinner than an edge; collapses cannot repeat forever). Keeps angles at least min(minAngle,
// what they were).
bool editTowardsFewerIntersections(HalfEdgeMesh& mesh, const ClosestPointTree& surface,
                                   const std::vector<int>& faces, double minAngle, double edgeLength,
                                   int pairs) {
    const CollapseLimits limits{2.0 * edgeLength, kEditMinNormalCosine, INFINITY};
    int fewestPairs = pairs;
    double bestTieAngle = -1.0;
    HalfEdgeMesh fewest = mesh, tie = mesh;
    for (int f : faces)
        for (int h = 3 * f; h < 3 * f + 3; ++h) {
            if (mesh.flipKeepsManifold(h)) {
                const HalfEdgeMesh::EditPreview flip = mesh.previewFlip(h);
                const double before =
                    std::min(mesh.faceMinAngle(f), mesh.faceMinAngle(HalfEdgeMesh::face(mesh.twin(h))));
                if (flip.minNormalCosine >= kEditMinNormalCosine &&
                    flip.minAngle >= std::min(minAngle, before)) {
                    HalfEdgeMesh trial = mesh;
                    trial.flipEdge(h);
                    if (const int count = countIntersections(trial); count < fewestPairs) {
                        fewestPairs = count;
                        fewest = std::move(trial);
                    }
                }
            }
            const CollapsePlan plan = planCollapse(mesh, surface, h, limits, CollapseGoal::LargestAngle);
            if (plan.valid && plan.minAngle >= std::min(minAngle, mesh.minAngleAroundEdge(h))) {
                HalfEdgeMesh trial = mesh;
                trial.collapseEdge(h, plan.position);
                const int count = countIntersections(trial);
                if (count < fewestPairs) {
                    fewestPairs = count;
                    fewest = std::move(trial);
                } else if (count == pairs && plan.minAngle > bestTieAngle) {
                    bestTieAngle = plan.minAngle;
                    tie = std::move(trial);
                }
            }
        }
    if (fewestPairs < pairs)
        mesh = std::move(fewest);
    else if (bestTieAngle >= 0.0)
        mesh = std::move(tie);
    else
        return false;
    return true;
}

}  // namespace

IntersectionSmoothingResult smoothSelfIntersections(HalfEdgeMesh& mesh, const ClosestPointTree& surface,
                                                    double minAngle, double edgeLength, int maxRounds) {
    IntersectionSmoothingResult result;
    int previousPairs = -1, rings = 0;
    for (;;) {
        mesh.compact();  // face f is triangle f of the exported mesh
        const auto pairs = findSelfIntersections(mesh.toTriangleMesh(""));
        result.remainingPairs = static_cast<int>(pairs.size());
        if (pairs.empty() || result.rounds == maxRounds) break;
        ++result.rounds;
        std::vector<int> faces;
        for (const auto& [a, b] : pairs) {
            faces.push_back(a);
            faces.push_back(b);
        }
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
        // Smoothing made no progress last round: flip or collapse where that helps, else smooth
        // a wider region, else stop.
        if (previousPairs >= 0 && result.remainingPairs >= previousPairs) {
            // Each trial edit costs a full intersection search: try those of the first few pairs.
            std::vector<int> firstFaces;
            for (std::size_t i = 0; i < pairs.size() && i < kEditPairs; ++i) {
                firstFaces.push_back(pairs[i].first);
                firstFaces.push_back(pairs[i].second);
            }
            std::sort(firstFaces.begin(), firstFaces.end());
            firstFaces.erase(std::unique(firstFaces.begin(), firstFaces.end()), firstFaces.end());
            if (editTowardsFewerIntersections(mesh, surface, firstFaces, minAngle, edgeLength,
                                              result.remainingPairs)) {
                ++result.edits;
                previousPairs = -1;
                continue;
            }
            if (rings == kMaxRings) break;
            ++rings;
        }
        previousPairs = result.remainingPairs;
        std::vector<int> vertices;
        for (int f : faces)
            for (int v : mesh.faceVertices(f)) vertices.push_back(v);
        auto deduplicate = [&vertices] {
            std::sort(vertices.begin(), vertices.end());
            vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        };
        deduplicate();
        for (int ring = 0; ring < rings; ++ring) {
            const std::size_t count = vertices.size();
            for (std::size_t i = 0; i < count; ++i)
                mesh.forEachOutgoing(vertices[i], [&](int h) { vertices.push_back(mesh.target(h)); });
            deduplicate();
        }
        for (int v : vertices)
            if (smoothVertex(mesh, v, minAngle)) ++result.moves;
    }
    return result;
}

}  // namespace btfracture
