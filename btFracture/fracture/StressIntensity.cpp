// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/StressIntensity.h>

#include <Eigen/Geometry>

#include <cmath>
#include <map>

namespace btfracture {

std::vector<FrontSifs> displacementCorrelation(const CrackMesh& cracks, const Eigen::VectorXd& cod,
                                               const Material& material) {
    const double Ep = material.planeStrainModulus(), mu = material.shearModulus();
    struct Sum {
        FrontSifs sifs;
        Eigen::Vector3d ahead = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
        int edges = 0;
    };
    std::map<int, Sum> perNode;
    for (const auto& e : cracks.frontEdges()) {
        const auto& tri = cracks.triangle(e.triangle);
        int c = tri[0];
        for (int v : tri)
            if (v != e.a && v != e.b) c = v;
        const Eigen::Vector3d a = cracks.node(e.a), b = cracks.node(e.b), behind = cracks.node(c);
        const Eigen::Vector3d s = (b - a).normalized();
        const Eigen::Vector3d n = cracks.normal(e.triangle);
        const Eigen::Vector3d m = s.cross(n);  // the interior lies on n x s, so this points ahead
        const Eigen::Vector3d toBehind = behind - a;
        const double r = (toBehind - toBehind.dot(s) * s).norm();
        const Eigen::Vector3d jump = cod.segment<3>(3 * c);
        const double scale = std::sqrt(2.0 * M_PI / r);
        const double KI = Ep / 8.0 * scale * jump.dot(n);
        const double KII = Ep / 8.0 * scale * jump.dot(m);
        const double KIII = mu / 4.0 * scale * jump.dot(m.cross(n));
        for (int v : {e.a, e.b}) {
            Sum& sum = perNode[v];
            sum.sifs.KI += KI;
            sum.sifs.KII += KII;
            sum.sifs.KIII += KIII;
            sum.sifs.spacing += (b - a).norm();
            sum.ahead += m;
            sum.normal += n;
            ++sum.edges;
        }
    }
    std::vector<FrontSifs> out;
    out.reserve(perNode.size());
    for (auto& [node, sum] : perNode) {
        FrontSifs f = sum.sifs;
        f.node = node;
        f.position = cracks.node(node);
        const double w = 1.0 / sum.edges;
        f.KI *= w;
        f.KII *= w;
        f.KIII *= w;
        f.spacing *= w;
        f.frame.normal = sum.normal.normalized();
        f.frame.ahead = (sum.ahead - sum.ahead.dot(f.frame.normal) * f.frame.normal).normalized();
        f.frame.tangent = f.frame.ahead.cross(f.frame.normal);
        f.compressive = f.KI < 0.0;
        out.push_back(f);
    }
    return out;
}

Eigen::Vector3d openingFromSifs(const FrontSifs& f, double distance, const Material& material) {
    const double mu = material.shearModulus(), nu = material.poissonRatio();
    const double scale = 2.0 * std::sqrt(2.0 * distance) / (mu * std::sqrt(M_PI));
    const double KI = f.compressive ? -std::abs(f.KI) : f.KI;
    return scale * ((1.0 - nu) * (KI * f.frame.normal + f.KII * f.frame.ahead) + f.KIII * f.frame.tangent);
}

}  // namespace btfracture
