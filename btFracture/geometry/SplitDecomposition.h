// SPDX-License-Identifier: Zlib
#pragma once
// Approximate convex decomposition of a closed mesh by recursive axis-aligned plane splits: the
// collision shape of fragments too large for HACD (dynamics/CollisionShapeBuilder.h; paper §5.2
// leaves them as triangle meshes). A part is the mesh's solid inside a box of cut planes; its
// piece is the convex hull of the mesh's triangles clipped to that box (their cut outlines bound
// the part's flat caps), so the pieces together cover the solid. The part whose hull exceeds its
// own volume most is split next, at the candidate plane that leaves the smallest summed hull
// volume, until every part's excess is within the tolerance or the piece budget is spent.
// Part volumes are counted on a grid of sample points inside the mesh (ray parity per column).
// Deterministic: the same mesh gives the same pieces.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

struct SplitDecompositionOptions {
    int maxPieces = 16;
    // A part is split while its hull volume exceeds its own volume by more than this fraction of
    // the mesh volume.
    double concavity = 0.02;
    int volumeSamples = 16384;  // grid points in the mesh's bounding box (about)
};

struct SplitDecomposition {
    std::vector<std::vector<Eigen::Vector3d>> pieces;  // points whose convex hull is one piece
    double meshVolume = 0.0;                           // [m^3]
    double hullVolume = 0.0;                           // summed hull volume of the pieces [m^3]
};

// Throws btfracture::Error naming mesh.name when the mesh encloses no volume or an option is out
// of range (maxPieces < 1, concavity < 0, volumeSamples < 1).
SplitDecomposition splitDecomposition(const TriangleMesh& mesh,
                                      const SplitDecompositionOptions& options = {});

}  // namespace btfracture
