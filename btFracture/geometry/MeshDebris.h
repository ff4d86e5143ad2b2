// SPDX-License-Identifier: Zlib
#pragma once
// Small closed pieces of a surface mesh that are not the body: islands a coarse level set leaves
// where a thin bridge or a sliver falls below its resolution, and cavities of a few voxels. A BEM
// needs one closed surface (bem/SurfaceMesh), so a level-set BEM source drops them.
#include <btFracture/core/TriangleMesh.h>

#include <vector>

namespace btfracture {

struct DroppedDebris {
    int pieces = 0;       // vertex-connected components removed
    double volume = 0.0;  // sum of their |enclosed volume| [m^3]
};

// Removes every vertex-connected component whose |enclosed volume| is below `fraction` of the
// largest one's (unreferenced vertices go too). A mesh of one component is left as it is.
DroppedDebris dropDebris(TriangleMesh& mesh, double fraction);

// Keeps the triangles t with keep[t] (in order) and the vertices they use (in first-use order).
void keepTriangles(TriangleMesh& mesh, const std::vector<char>& keep);

}  // namespace btfracture
