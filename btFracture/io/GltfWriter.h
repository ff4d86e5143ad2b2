// SPDX-License-Identifier: Zlib
#pragma once
// glTF 2.0 binary (.glb) of rigid bodies in motion: one node per body with its mesh (body frame,
// two primitives: the materials "outside" and "interior", the latter for crack faces), and one
// animation whose translation and rotation keys are the bodies' poses at the sample times
// (linear). A body that appears after the first sample or is removed is hidden by scale keys 0
// (step interpolation) before it appears and from its removal on; a body that never moves has no
// keys. Units: metres and seconds, +y up as in the scenes. No normals: viewers shade flat.
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace btfracture {

struct GltfBody {
    std::string name;
    TriangleMesh surface;          // body frame [m]
    std::vector<bool> crackFaces;  // per triangle: interior material; empty: all outside
    int firstSample = 0;           // the sample it appears at
    // Its pose at samples firstSample, firstSample + 1, ... (at least one).
    std::vector<Eigen::Vector3d> positions;
    std::vector<Eigen::Quaterniond> orientations;
    bool removed = false;  // hidden from sample firstSample + positions.size() on
};

// Writes `bodies` with `times` [s] (strictly increasing) to `path`. Throws btfracture::Error
// naming the file for inconsistent input or when it cannot be written.
void writeGlb(const std::string& path, const std::vector<double>& times, const std::vector<GltfBody>& bodies);

}  // namespace btfracture
