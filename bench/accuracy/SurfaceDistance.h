// SPDX-License-Identifier: Zlib
#pragma once
// Distance between two fracture surfaces (triangle meshes, e.g. a method's crack sheets and the
// reference run's): the symmetric Hausdorff distance (geometry/SurfaceDistance.h) and the mean
// distance of the vertices and triangle centroids of each to the other surface, averaged over
// both directions [m].
#include <btFracture/core/TriangleMesh.h>

namespace accuracy {

struct SurfaceDistance {
    double hausdorff = -1.0, mean = -1.0;  // -1 when a mesh is empty
};

SurfaceDistance surfaceDistance(const btfracture::TriangleMesh& a, const btfracture::TriangleMesh& b);

}  // namespace accuracy
