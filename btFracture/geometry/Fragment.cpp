// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/Fragment.h>

#include <btFracture/core/MassProperties.h>

namespace btfracture {

bool holdsVolume(const TriangleMesh& mesh, double volume) {
    return mesh.triangles.size() >= 4 && enclosedVolume(mesh) >= 0.1 * volume;
}

}  // namespace btfracture
