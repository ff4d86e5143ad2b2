// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/StressIntensity.h>

#include <btFracture/core/ClosestPoint.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace btfracture {
namespace {

// The fit window, in units of the node's front spacing h: crack nodes between kNearRow and
// kFarRow from the front, within kAlong of the node along it (hat-weighted); on a convex front
// of curvature kappa no farther than kCurvedReach / kappa (the profile's curvature term then
// stays below 20 %), and never farther than kSizeReach times the sheet's extent behind the node
// (inside the square-root zone of a straight front: a notched beam's fit over half its crack
// depth is +15 %). Fronts whose window reaches less than kResolvedRows h keep the first row.
constexpr double kNearRow = 1.5, kFarRow = 4.5, kAlong = 2.5, kCurvedReach = 0.75, kSizeReach = 0.25,
                 kResolvedRows = 2.5;

double segmentDistance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return (x - closestPointOnSegment(x, a, b)).norm();
}

// Frames and spacings per front node, averaged over its front edges; `edgesAtNode` lists the
// front edges at each front node.
std::vector<FrontSifs> frontFrames(const CrackMesh& cracks, std::map<int, std::vector<int>>& edgesAtNode) {
    struct Sum {
        Eigen::Vector3d ahead = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
        double spacing = 0.0;
        int edges = 0;
    };
    std::map<int, Sum> perNode;
    const auto& front = cracks.frontEdges();
    for (int i = 0; i < static_cast<int>(front.size()); ++i) {
        const auto& e = front[i];
        const Eigen::Vector3d a = cracks.node(e.a), b = cracks.node(e.b);
        const Eigen::Vector3d n = cracks.normal(e.triangle);
        const Eigen::Vector3d m = (b - a).normalized().cross(n);  // the interior lies on n x s
        for (int v : {e.a, e.b}) {
            Sum& sum = perNode[v];
            sum.spacing += (b - a).norm();
            sum.ahead += m;
            sum.normal += n;
            ++sum.edges;
            edgesAtNode[v].push_back(i);
        }
    }
    std::vector<FrontSifs> out;
    out.reserve(perNode.size());
    for (const auto& [node, sum] : perNode) {
        FrontSifs f;
        f.node = node;
        f.position = cracks.node(node);
        f.spacing = sum.spacing / sum.edges;
        f.frame.normal = sum.normal.normalized();
        f.frame.ahead = (sum.ahead - sum.ahead.dot(f.frame.normal) * f.frame.normal).normalized();
        f.frame.tangent = f.frame.ahead.cross(f.frame.normal);
        out.push_back(f);
    }
    return out;
}

// In-plane curvature of the front at node f (the circle through it and its two front
// neighbours), positive where the crack is convex (the centre lies behind the front).
double frontCurvature(const CrackMesh& cracks, const FrontSifs& f, const std::vector<int>& edges) {
    if (edges.size() != 2) return 0.0;
    const auto& front = cracks.frontEdges();
    Eigen::Vector3d before = f.position, after = f.position;
    for (int i : edges) {
        if (front[i].a == f.node) after = cracks.node(front[i].b);
        if (front[i].b == f.node) before = cracks.node(front[i].a);
    }
    const Eigen::Vector3d a = before - f.position, b = after - f.position;
    const double denominator = a.norm() * b.norm() * (after - before).norm();
    if (!(denominator > 0.0)) return 0.0;
    const double kappa = 2.0 * a.cross(b).norm() / denominator;
    return (a + b).dot(f.frame.ahead) > 0.0 ? -kappa : kappa;
}

// First-row correlation (straight-front profile): per front edge, the opening at the node
// opposite it over g = sqrt(r / 2 pi), r its distance from the edge, in the edge's frame
// (n, m, t); averaged per front node over its edges.
std::map<int, Eigen::Vector3d> firstRowAmplitudes(const CrackMesh& cracks, const Eigen::VectorXd& cod) {
    std::map<int, std::pair<Eigen::Vector3d, int>> sum;  // sum of cod / g in the node's frame
    for (const auto& e : cracks.frontEdges()) {
        const auto& tri = cracks.triangle(e.triangle);
        int c = tri[0];
        for (int v : tri)
            if (v != e.a && v != e.b) c = v;
        const Eigen::Vector3d a = cracks.node(e.a), b = cracks.node(e.b), toBehind = cracks.node(c) - a;
        const Eigen::Vector3d s = (b - a).normalized(), n = cracks.normal(e.triangle), m = s.cross(n);
        const double g = std::sqrt((toBehind - toBehind.dot(s) * s).norm() / (2.0 * M_PI));
        const Eigen::Vector3d jump = cod.segment<3>(3 * c);
        const Eigen::Vector3d k(jump.dot(n) / g, jump.dot(m) / g, jump.dot(m.cross(n)) / g);
        for (int v : {e.a, e.b}) {
            auto& entry = sum.try_emplace(v, Eigen::Vector3d::Zero(), 0).first->second;
            entry.first += k;
            ++entry.second;
        }
    }
    std::map<int, Eigen::Vector3d> out;
    for (const auto& [node, entry] : sum) out[node] = entry.first / entry.second;
    return out;
}

// Per front node: how far its sheet reaches behind it, max over the sheet's nodes x of
// (f - x) . ahead [m].
std::map<int, double> extentBehind(const CrackMesh& cracks, const std::vector<FrontSifs>& frames) {
    std::vector<std::vector<int>> nodesOfSheet(cracks.sheetCount());
    std::vector<int> sheetOfNode(cracks.nodeCount(), -1);
    for (int t = 0; t < cracks.triangleCount(); ++t)
        for (int v : cracks.triangle(t))
            if (sheetOfNode[v] < 0) {
                sheetOfNode[v] = cracks.sheetOf(t);
                nodesOfSheet[sheetOfNode[v]].push_back(v);
            }
    std::map<int, double> out;
    for (const FrontSifs& f : frames) {
        double extent = 0.0;
        for (int v : nodesOfSheet[sheetOfNode[f.node]])
            extent = std::max(extent, (f.position - cracks.node(v)).dot(f.frame.ahead));
        out[f.node] = extent;
    }
    return out;
}

}  // namespace

std::vector<FrontSifs> displacementCorrelation(const CrackMesh& cracks, const Eigen::VectorXd& cod,
                                               const Material& material) {
    const double Ep = material.planeStrainModulus(), mu = material.shearModulus();
    std::map<int, std::vector<int>> edgesAtNode;
    std::vector<FrontSifs> out = frontFrames(cracks, edgesAtNode);
    if (cod.size() == 0 || cod.isZero(0.0)) return out;  // frames only (EST)
    const auto& front = cracks.frontEdges();
    const std::map<int, Eigen::Vector3d> firstRow = firstRowAmplitudes(cracks, cod);
    const std::map<int, double> extent = extentBehind(cracks, out);
    for (FrontSifs& f : out) {
        const double kappa = frontCurvature(cracks, f, edgesAtNode[f.node]);
        const double h = f.spacing, along = kAlong * h;
        double reach = std::min(kFarRow * h, kSizeReach * extent.at(f.node));
        if (kappa > 0.0) reach = std::min(reach, kCurvedReach / kappa);
        // One-parameter least squares per mode: cod = c K sqrt(r / 2 pi) sqrt(1 - kappa r / 2)
        // over the nodes in the window (c = 8 / E' for modes I and II, 4 / mu for mode III).
        // A front resolved by fewer than kResolvedRows rows within the reach (a small, young or
        // strongly curved sheet), or with no node in the window, keeps the first row.
        Eigen::Vector3d k = firstRow.at(f.node);
        if (reach >= kResolvedRows * h) {
            // Crack nodes near f (grown across the sheet from f's triangles while within 5.5 h),
            // and the front edges among their triangles.
            std::set<int> region, nearFront, nodes;
            std::vector<int> queue(cracks.trianglesAtNode(f.node).begin(),
                                   cracks.trianglesAtNode(f.node).end());
            region.insert(queue.begin(), queue.end());
            for (std::size_t q = 0; q < queue.size(); ++q)
                for (int v : cracks.triangle(queue[q])) {
                    if (const auto it = edgesAtNode.find(v); it != edgesAtNode.end())
                        nearFront.insert(it->second.begin(), it->second.end());
                    if (!cracks.isFront(v)) nodes.insert(v);
                    if ((cracks.node(v) - f.position).norm() > (kFarRow + 1.0) * h) continue;
                    for (int t : cracks.trianglesAtNode(v))
                        if (region.insert(t).second) queue.push_back(t);
                }
            double gg = 0.0;
            Eigen::Vector3d gc = Eigen::Vector3d::Zero();
            for (int v : nodes) {
                const Eigen::Vector3d x = cracks.node(v);
                double r = std::numeric_limits<double>::infinity();
                for (int i : nearFront)
                    r = std::min(r, segmentDistance(x, cracks.node(front[i].a), cracks.node(front[i].b)));
                const double s = std::abs((x - f.position).dot(f.frame.tangent));
                if (!(r > kNearRow * h) || r > reach || s >= along) continue;
                const double w = 1.0 - s / along;
                const double g = std::sqrt(r / (2.0 * M_PI) * std::max(0.1, 1.0 - 0.5 * kappa * r));
                const Eigen::Vector3d jump = cod.segment<3>(3 * v);
                gg += w * g * g;
                gc += w * g *
                      Eigen::Vector3d(jump.dot(f.frame.normal), jump.dot(f.frame.ahead),
                                      jump.dot(f.frame.tangent));
            }
            if (gg > 0.0) k = gc / gg;
        }
        f.KI = Ep / 8.0 * k(0);
        f.KII = Ep / 8.0 * k(1);
        f.KIII = mu / 4.0 * k(2);
        f.compressive = f.KI < 0.0;
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
