// SPDX-License-Identifier: Zlib
#include <btFracture/core/ClosestPoint.h>

namespace btfracture {

TriangleClosestPoint closestPointAndFeature(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    using F = TriangleFeature;
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return {a, F::VertexA};
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return {b, F::VertexB};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0 && d1 - d3 > 0) return {a + (d1 / (d1 - d3)) * ab, F::EdgeAB};
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return {c, F::VertexC};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0 && d2 - d6 > 0) return {a + (d2 / (d2 - d6)) * ac, F::EdgeCA};
    const double va = d3 * d6 - d5 * d4;
    const double e1 = d4 - d3, e2 = d5 - d6;
    if (va <= 0 && e1 >= 0 && e2 >= 0 && e1 + e2 > 0) return {b + (e1 / (e1 + e2)) * (c - b), F::EdgeBC};
    const double sum = va + vb + vc;
    if (!(sum > 0)) {  // degenerate triangle: the nearest corner
        const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
        if (da <= db && da <= dc) return {a, F::VertexA};
        return db <= dc ? TriangleClosestPoint{b, F::VertexB} : TriangleClosestPoint{c, F::VertexC};
    }
    return {a + ab * (vb / sum) + ac * (vc / sum), F::Face};
}

}  // namespace btfracture
