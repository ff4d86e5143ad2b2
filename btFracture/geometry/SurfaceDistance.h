// SPDX-License-Identifier: Zlib
#pragma once
// Distances between two triangulated surfaces, measured by sampling one surface and finding
// the closest point on the other (ClosestPointTree).
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/ClosestPointTree.h>

namespace btfracture {

// Largest distance [mesh units] from a sample point of `from` to the surface in `to`. Samples:
// the vertices plus a barycentric grid on every triangle with spacing at most `sampleSpacing`
// [mesh units], so the true one-sided distance exceeds the result by at most sampleSpacing / 2.
// Throws btfracture::Error if `from` is empty or sampleSpacing is not positive.
double maxDistanceToSurface(const TriangleMesh& from, const ClosestPointTree& to, double sampleSpacing);

// Symmetric Hausdorff distance [mesh units] between two surfaces, both sampled with spacing
// relativeSpacing times the diagonal of their joint bounding box.
double hausdorffDistance(const TriangleMesh& a, const TriangleMesh& b, double relativeSpacing = 0.005);

}  // namespace btfracture
