// SPDX-License-Identifier: Zlib
#pragma once
// A mesh whose vertices lie on a curved surface cuts inside it where the surface is convex (and
// bulges outside where it is concave): a remeshed sphere with 500 triangles has about 1.5 %
// less volume than the sphere. fitAcrossSurface() moves each vertex along its normal so that,
// on average over the vertex's triangles, the mesh lies as much outside the surface as inside;
// this restores the enclosed volume and halves the chordal error.
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/HalfEdgeMesh.h>

namespace btfracture {

struct SurfaceFitResult {
    int limitedVertices = 0;     // offsets cut back to maxOffset
    int keptVertices = 0;        // left where they were to keep angles and avoid intersections
    double largestOffset = 0.0;  // [mesh units]
};

// The signed distance of each triangle from the surface is averaged at its edge midpoints
// (exact for a quadratic surface); each vertex moves by minus the area-weighted mean of its
// triangles, at most maxOffset [mesh units]. A vertex whose move would leave one of its
// triangles with an angle below minAngle [rad] (if it was above before), turn a triangle by
// more than 60 degrees or make it intersect another triangle stays where it was.
SurfaceFitResult fitAcrossSurface(HalfEdgeMesh& mesh, const ClosestPointTree& surface, double minAngle,
                                  double maxOffset);

}  // namespace btfracture
