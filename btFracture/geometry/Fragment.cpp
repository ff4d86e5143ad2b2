// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/Fragment.h>

#include <btFracture/core/MassProperties.h>

namespace btfracture {

bool holdsVolume(const TriangleMesh& mesh, double volume, const Eigen::Vector3d& centreOfMass) {
    return mesh.triangles.size() >= 4 && enclosedVolume(mesh, centreOfMass) >= 0.1 * volume;
}

}  // namespace btfracture
