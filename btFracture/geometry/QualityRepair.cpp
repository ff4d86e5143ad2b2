// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/QualityRepair.h>

#include <btFracture/geometry/RemeshEdits.h>

#include <algorithm>

namespace btfracture {
namespace {

constexpr double kMinNormalCosine = 0.5;  // no edit turns a face by more than 60 degrees
constexpr double kGain = 1e-6;            // smallest angle gain [rad] that counts as progress

enum class EditKind { None, Flip, Collapse, Move };

struct Edit {
    EditKind kind = EditKind::None;
    int element = -1;  // halfedge (flip, collapse) or vertex (move)
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    double minAngle = 0.0;  // smallest angle of the touched region after the edit
};

// The edit around face f that leaves its region with the largest smallest angle, among those
// that raise the region's smallest angle at all.
Edit bestEditForFace(const HalfEdgeMesh& mesh, const ClosestPointTree& surface, int f, double edgeLength) {
    Edit best;
    auto consider = [&best](EditKind kind, int element, const Eigen::Vector3d& position, double before,
                            double after) {
        if (after > before + kGain && (best.kind == EditKind::None || after > best.minAngle)) {
            best.kind = kind;
            best.element = element;
            best.position = position;
            best.minAngle = after;
        }
    };
    const CollapseLimits limits{5.0 / 3.0 * edgeLength, kMinNormalCosine, INFINITY};
    for (int h = 3 * f; h < 3 * f + 3; ++h) {
        if (mesh.flipKeepsManifold(h)) {
            const HalfEdgeMesh::EditPreview flip = mesh.previewFlip(h);
            if (flip.minNormalCosine >= kMinNormalCosine)
                consider(EditKind::Flip, h, Eigen::Vector3d::Zero(),
                         std::min(mesh.faceMinAngle(f), mesh.faceMinAngle(HalfEdgeMesh::face(mesh.twin(h)))),
                         flip.minAngle);
        }
        const CollapsePlan collapse = planCollapse(mesh, surface, h, limits, CollapseGoal::LargestAngle);
        if (collapse.valid)
            consider(EditKind::Collapse, h, collapse.position, mesh.minAngleAroundEdge(h), collapse.minAngle);
    }
    for (int v : mesh.faceVertices(f)) {
        const VertexMove move = optimizeVertexAngles(mesh, surface, v, 0.25 * edgeLength, kMinNormalCosine);
        if (move.improved)
            consider(EditKind::Move, v, move.position, mesh.minAngleAroundVertex(v), move.minAngle);
    }
    return best;
}

}  // namespace

QualityRepairResult repairSmallAngles(HalfEdgeMesh& mesh, const ClosestPointTree& surface, double minAngle,
                                      double edgeLength, int maxPasses) {
    QualityRepairResult result;
    for (int pass = 0; pass < maxPasses; ++pass) {
        int edits = 0;
        // Flip the edges of bad faces wherever that raises the smaller angle of the pair.
        for (int h = 0; h < mesh.halfedgeSlots(); ++h) {
            if (!mesh.halfedgeAlive(h) || mesh.twin(h) < h) continue;
            const double before = std::min(mesh.faceMinAngle(HalfEdgeMesh::face(h)),
                                           mesh.faceMinAngle(HalfEdgeMesh::face(mesh.twin(h))));
            if (before >= minAngle || !mesh.flipKeepsManifold(h)) continue;
            const HalfEdgeMesh::EditPreview flip = mesh.previewFlip(h);
            if (flip.minNormalCosine >= kMinNormalCosine && flip.minAngle > before + kGain) {
                mesh.flipEdge(h);
                ++edits;
            }
        }
        // Then the best local edit for every face that is still bad.
        for (int f = 0; f < mesh.faceSlots(); ++f) {
            if (!mesh.faceAlive(f) || mesh.faceMinAngle(f) >= minAngle) continue;
            const Edit edit = bestEditForFace(mesh, surface, f, edgeLength);
            switch (edit.kind) {
                case EditKind::None:
                    continue;
                case EditKind::Flip:
                    mesh.flipEdge(edit.element);
                    break;
                case EditKind::Collapse:
                    mesh.collapseEdge(edit.element, edit.position);
                    break;
                case EditKind::Move:
                    mesh.setPosition(edit.element, edit.position);
                    break;
            }
            ++edits;
        }
        result.edits += edits;
        result.passes = pass + 1;
        if (edits == 0) break;
    }
    for (int f = 0; f < mesh.faceSlots(); ++f)
        if (mesh.faceAlive(f) && mesh.faceMinAngle(f) < minAngle) ++result.trianglesBelow;
    return result;
}

}  // namespace btfracture
