// SPDX-License-Identifier: Zlib
#pragma once
// Which faces of a fragment's surface are crack faces (the "interior" material of the outputs):
// a face lies on the unbroken original's surface when its centroid is within `tolerance` of it
// and it faces the same way (normals within 60 degrees); every other face was made by a cut.
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/geometry/ClosestPointTree.h>

#include <Eigen/Geometry>

#include <vector>

namespace btfracture {

// The two materials of the outputs' surfaces (OBJ usemtl, glTF materials): "outside" for the
// original surface, "interior" for crack faces. Colours: linear RGB in [0, 1].
struct SurfaceMaterial {
    const char* name;
    float rgb[3];
};
inline constexpr SurfaceMaterial kOutsideMaterial{"outside", {0.70f, 0.70f, 0.66f}};
inline constexpr SurfaceMaterial kInteriorMaterial{"interior", {0.80f, 0.35f, 0.12f}};

// `fragment`'s faces, true for a crack face. `originalFromFragment` maps the fragment's body
// frame into the frame of `original` (the unbroken body's surface); `tolerance` [m].
std::vector<bool> crackFaces(const TriangleMesh& fragment, const Eigen::Isometry3d& originalFromFragment,
                             const ClosestPointTree& original, double tolerance);

}  // namespace btfracture
