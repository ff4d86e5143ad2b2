// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/CrackSeed.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <Eigen/Geometry>

#include <cmath>

namespace btfracture {
namespace {

// Node i of ring k of the hexagonal lattice in the plane (u, v) about `centre`, the ring's first
// corner at polar angle `start`: the point i / k of the way round the hexagon's sides (a corner
// every k nodes), moved onto the circle of radius r at its polar angle, which keeps the triangles
// close to equilateral (no 120-degree corners).
Eigen::Vector3d latticeNode(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                            double r, int k, int i, double start) {
    const int side = i / k;
    const double along = double(i % k) / k;
    const double a0 = start + side * M_PI / 3.0, a1 = a0 + M_PI / 3.0;
    const Eigen::Vector2d hex = (1.0 - along) * Eigen::Vector2d(pmath::cos(a0), pmath::sin(a0)) +
                                along * Eigen::Vector2d(pmath::cos(a1), pmath::sin(a1));
    const double angle = pmath::atan2(hex.y(), hex.x());
    return centre + r * (pmath::cos(angle) * u + pmath::sin(angle) * v);
}

}  // namespace

std::vector<int> addDiscCrack(CrackMesh& cracks, const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                              double radius, int rings, double rotation) {
    if (!(radius > 0.0) || rings < 1 || !(normal.norm() > 0.0))
        throw Error("addDiscCrack: radius must be positive, rings at least 1 and the normal non-zero");
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
    // Hexagonal lattice rings: ring k has 6 k nodes, on the circle of radius R k / rings.
    std::vector<std::vector<int>> ring(rings + 1);
    ring[0].push_back(cracks.addNode(centre));
    for (int k = 1; k <= rings; ++k)
        for (int i = 0; i < 6 * k; ++i)
            ring[k].push_back(cracks.addNode(latticeNode(centre, u, v, radius * k / rings, k, i, rotation)));
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

std::vector<int> addHalfDiscCrack(CrackMesh& cracks, const Eigen::Vector3d& centre,
                                  const Eigen::Vector3d& normal, const Eigen::Vector3d& inward, double radius,
                                  int rings) {
    if (!(radius > 0.0) || rings < 1 || !(normal.norm() > 0.0))
        throw Error("addHalfDiscCrack: radius must be positive, rings at least 1 and the normal non-zero");
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Vector3d u = (inward - inward.dot(n) * n).normalized(), v = n.cross(u);
    if (!u.allFinite()) throw Error("addHalfDiscCrack: the inward direction lies along the crack normal");
    // Half the hexagonal lattice of addDiscCrack: ring k runs over three hexagon sides from the
    // polar angle -90 to +90 degrees about u (counter-clockwise about n), its 3 k + 1 nodes on the
    // circle of radius R k / rings.
    std::vector<std::vector<int>> ring(rings + 1);
    ring[0].push_back(cracks.addNode(centre));
    for (int k = 1; k <= rings; ++k)
        for (int i = 0; i <= 3 * k; ++i)
            ring[k].push_back(
                cracks.addNode(latticeNode(centre, u, v, radius * k / rings, k, i, -0.5 * M_PI)));
    std::vector<int> added;
    for (int k = 1; k <= rings; ++k) {
        const auto& inner = ring[k - 1];
        const auto& outer = ring[k];
        const int li = static_cast<int>(inner.size()) - 1, lo = static_cast<int>(outer.size()) - 1;
        // Both open rings walked by their fraction of the half circle (i / li against o / lo,
        // exactly in integers); the outer ring advances when its next node comes strictly first.
        int i = 0, o = 0;
        while (i < li || o < lo) {
            const bool outerFirst = i >= li || (o < lo && (o + 1) * li < (i + 1) * lo);
            if (outerFirst) {
                added.push_back(cracks.addTriangle(inner[i], outer[o], outer[o + 1]));
                ++o;
            } else {
                added.push_back(cracks.addTriangle(inner[i], outer[o], inner[i + 1]));
                ++i;
            }
        }
    }
    return added;
}

}  // namespace btfracture
