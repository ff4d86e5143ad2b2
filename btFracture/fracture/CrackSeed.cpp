// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/CrackSeed.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <Eigen/Geometry>

#include <cmath>

namespace btfracture {

std::vector<int> addDiscCrack(CrackMesh& cracks, const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                              double radius, int rings, double rotation) {
    if (!(radius > 0.0) || rings < 1 || !(normal.norm() > 0.0))
        throw Error("addDiscCrack: radius must be positive, rings at least 1 and the normal non-zero");
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
    // Hexagonal lattice rings: ring k has 6 k nodes on a hexagon of "radius" k, then each node
    // is moved onto the circle of radius R k / rings at its polar angle, which keeps the
    // triangles close to equilateral (no 120-degree corners).
    std::vector<std::vector<int>> ring(rings + 1);
    ring[0].push_back(cracks.addNode(centre));
    for (int k = 1; k <= rings; ++k)
        for (int i = 0; i < 6 * k; ++i) {
            const int side = i / k;
            const double along = double(i % k) / k;
            const double a0 = rotation + side * M_PI / 3.0, a1 = a0 + M_PI / 3.0;
            const Eigen::Vector2d hex = (1.0 - along) * Eigen::Vector2d(pmath::cos(a0), pmath::sin(a0)) +
                                        along * Eigen::Vector2d(pmath::cos(a1), pmath::sin(a1));
            const double angle = pmath::atan2(hex.y(), hex.x());
            const double r = radius * k / rings;
            ring[k].push_back(cracks.addNode(centre + r * (pmath::cos(angle) * u + pmath::sin(angle) * v)));
        }
    std::vector<int> added;
    for (int k = 1; k <= rings; ++k) {
        const auto& inner = ring[k - 1];
        const auto& outer = ring[k];
        const int ni = static_cast<int>(inner.size()), no = static_cast<int>(outer.size());
        // Walk both rings by perimeter fraction (i / ni against o / no, compared exactly in
        // integers): the outer ring advances when its next node comes strictly first, which
        // reproduces the lattice's strip triangulation.
        int i = 0, o = 0;
        while (o < no || (ni > 1 && i < ni)) {
            const bool outerFirst = ni == 1 || i >= ni || (o < no && (o + 1) * ni < (i + 1) * no);
            if (outerFirst) {
                added.push_back(cracks.addTriangle(inner[i % ni], outer[o], outer[(o + 1) % no]));
                ++o;
            } else {
                added.push_back(cracks.addTriangle(inner[i % ni], outer[o % no], inner[(i + 1) % ni]));
                ++i;
            }
        }
    }
    return added;
}

}  // namespace btfracture
