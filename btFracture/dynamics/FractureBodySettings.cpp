// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FractureBodySettings.h>

#include <btFracture/core/Error.h>
#include <btFracture/geometry/ConvexHull.h>

#include <cmath>
#include <sstream>

namespace btfracture {

void validate(const FractureBodySettings& s, const std::string& body) {
    const std::string where = body + ": fracture settings";
    s.validate(where);  // method and its threshold
    s.materialNoise.validate(where);
    std::ostringstream problem;
    if (!(s.impulseThreshold >= 0.0) || !std::isfinite(s.impulseThreshold))
        problem << "impulseThreshold " << s.impulseThreshold << " N s (need finite, >= 0)";
    else if (s.bemTriangleTarget < 4)
        problem << "bemTriangleTarget " << s.bemTriangleTarget << " (need >= 4)";
    else if (s.collisionTriangleTarget < s.bemTriangleTarget)
        problem << "collisionTriangleTarget " << s.collisionTriangleTarget << " (need >= bemTriangleTarget "
                << s.bemTriangleTarget << ")";
    else if (!(s.voxelSize >= 0.0) || !std::isfinite(s.voxelSize))
        problem << "voxelSize " << s.voxelSize << " m (need finite, >= 0)";
    else if (s.maxRefractureDepth < 0)
        problem << "maxRefractureDepth " << s.maxRefractureDepth << " (need >= 0)";
    else if (s.refractureDepth < 0)
        problem << "refractureDepth " << s.refractureDepth << " (need >= 0)";
    if (problem.tellp() > 0) throw Error(where + ": " + problem.str());
}

CollisionShapeKind collisionShapeKind(const FractureBodySettings& settings, const TriangleMesh& mesh) {
    if (isConvex(mesh)) return CollisionShapeKind::ConvexHull;
    const bool breaks = settings.fracturable && settings.refractureDepth <= settings.maxRefractureDepth;
    if (breaks && settings.concaveShapeKind == CollisionShapeKind::ConvexDecomposition &&
        !settings.shapeOptions.fitsHacd(mesh.triangles.size()))
        return CollisionShapeKind::GImpactMesh;
    return settings.concaveShapeKind;
}

}  // namespace btfracture
