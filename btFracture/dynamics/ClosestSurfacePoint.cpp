#include <btFracture/dynamics/ClosestSurfacePoint.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace btfracture {

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) return a + d1 / (d1 - d3) * ab;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    const double e1 = d4 - d3, e2 = d5 - d6;
    if (va <= 0.0 && e1 >= 0.0 && e2 >= 0.0 && e1 + e2 > 0.0) return b + e1 / (e1 + e2) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {  // degenerate triangle: nearest of its corners
        const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
        return da <= db && da <= dc ? a : (db <= dc ? b : c);
    }
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

namespace {

Eigen::Vector3d barycentricOf(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    if (!(n2 > 0.0)) return Eigen::Vector3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    const double u = (c - b).cross(q - b).dot(n) / n2;
    const double v = (a - c).cross(q - c).dot(n) / n2;
    return Eigen::Vector3d(u, v, 1.0 - u - v);
}

}  // namespace

ClosestSurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
    ClosestSurfacePoint best;
    double bestDistance2 = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        const Eigen::Vector3d q =
            closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        const double d2 = (q - p).squaredNorm();
        if (d2 < bestDistance2) {
            bestDistance2 = d2;
            best.triangle = static_cast<int>(e);
            best.point = q;
        }
    }
    if (best.triangle < 0) return best;
    const auto& t = mesh.triangles[best.triangle];
    best.barycentric =
        barycentricOf(best.point, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    best.distance = std::sqrt(bestDistance2);
    return best;
}

}  // namespace btfracture
