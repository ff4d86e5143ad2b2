// SPDX-License-Identifier: Zlib
#pragma once
// A btConvexHullShape whose support queries walk the hull's corner graph instead of scanning
// every corner. Bullet's support query is a linear scan (Debian's Bullet has no SIMD maxDot),
// and GJK, the CCD sweeps and the separated-pair bounds call it several times per pair and
// step; fragments' hulls carry 100-2,000 corners.
//
// A query starts at the better of the last answer and the corner extreme along the query's
// dominant axis, and moves to the best neighbour while one is larger (on a convex polytope a
// local maximum of a linear function is the global one). The answer is the point Bullet's scan
// returns, the largest value and the first index among equal ones: where corners come within
// kTieMargin of the hull's size of the best value (a face or edge nearly perpendicular to the
// direction), all of them and every point that is not a corner are compared; more than
// kMaxPlateau such corners, or a zero or non-finite direction, and the query scans like Bullet.
// Away from near ties, the points that are not corners and lie nearest the chosen corner are
// compared with it (only such a point can beat it, by rounding). The start only changes how far
// the walk goes.
//
// The shape type is CUSTOM_POLYHEDRAL_SHAPE_TYPE, so that Bullet's non-virtual support switch
// (which scans CONVEX_HULL_SHAPE_PROXYTYPE inline) calls this class; Bullet's default collision
// configuration treats it as any other convex shape. It is still a btConvexHullShape
// (getUnscaledPoints, getNumPoints) and is written to .bullet files as one.
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <atomic>
#include <vector>

namespace btfracture {

class GraphHullShape : public btConvexHullShape {
public:
    // `points` (count of them, stride in bytes as btConvexHullShape's constructor); at least
    // four affinely independent points for the graph, otherwise every query scans.
    GraphHullShape(const btScalar* points, int count, int stride);

    btVector3 localGetSupportingVertexWithoutMargin(const btVector3& direction) const override;
    void batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* directions, btVector3* out,
                                                           int count) const override;
    const char* getName() const override { return "Convex"; }
    // Serialized as a plain btConvexHullShape (CONVEX_HULL_SHAPE_PROXYTYPE), which Bullet's
    // importers know.
    const char* serialize(void* dataBuffer, btSerializer* serializer) const override;

    // Corners in the graph (0 when every query scans).
    int graphCorners() const { return static_cast<int>(offsets_.empty() ? 0 : offsets_.size() - 1); }

private:
    int climb(const btVector3& direction) const;  // index into getUnscaledPoints(), or -1 to scan

    // Corner graph in compressed rows: corner c's neighbours are corners
    // neighbours_[offsets_[c] .. offsets_[c + 1]); pointIndex_[c] is its index among the points.
    std::vector<int> offsets_, neighbours_, pointIndex_;
    int axisExtreme_[6] = {0, 0, 0, 0, 0, 0};  // corner extreme along +x, -x, +y, -y, +z, -z
    btAlignedObjectArray<btVector3> corners_;  // corner c is getUnscaledPoints()[pointIndex_[c]]
    // Points that are not corners: all of them, and by nearest corner (compressed rows).
    std::vector<int> extras_, shadowOffsets_, shadowPoints_;
    btScalar size_ = 0;                 // largest |point| (unscaled)
    mutable std::atomic<int> last_{0};  // corner of the last answer (a start only)
};

}  // namespace btfracture
