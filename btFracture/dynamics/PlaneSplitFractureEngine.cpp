// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/PlaneSplitFractureEngine.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/TractionBalance.h>
#include <btFracture/dynamics/btFractureRigidBody.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace btfracture {
namespace {

// The engine's per-body state: the Eq. 6 balancer on the body mesh (its stand-in "BEM").
class PlaneSplitState : public FractureState {
public:
    explicit PlaneSplitState(const TriangleMesh& mesh) : balancer(mesh) {}
    TractionBalancer balancer;
};

TriangleMesh half(const TriangleMesh& mesh, const std::vector<double>& distance, double side,
                  const Eigen::Vector3d& normal, const std::string& name) {
    TriangleMesh out;
    out.name = name;
    std::vector<int> kept(mesh.vertices.size(), -1);
    std::map<std::pair<int, int>, int> cut;  // undirected edge -> vertex on the plane
    auto keep = [&](int v) {
        if (kept[v] < 0) {
            kept[v] = static_cast<int>(out.vertices.size());
            out.vertices.push_back(mesh.vertices[v]);
        }
        return kept[v];
    };
    auto cutPoint = [&](int a, int b) {
        const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
        auto [it, inserted] = cut.emplace(key, static_cast<int>(out.vertices.size()));
        if (inserted) {
            // Same arithmetic for both halves (canonical edge order): the cut vertices coincide.
            const double t = distance[key.first] / (distance[key.first] - distance[key.second]);
            out.vertices.push_back(mesh.vertices[key.first] +
                                   t * (mesh.vertices[key.second] - mesh.vertices[key.first]));
        }
        return it->second;
    };
    for (const auto& tri : mesh.triangles) {
        std::vector<int> polygon;
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            const bool inA = side * distance[a] > 0.0, inB = side * distance[b] > 0.0;
            if (inA) polygon.push_back(keep(a));
            if (inA != inB) polygon.push_back(cutPoint(a, b));
        }
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
            out.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
    if (cut.size() < 3) return out;
    // Cap: the cut vertices in angular order around their centroid, fanned from it, facing -side*n.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& [edge, v] : cut) centre += out.vertices[v];
    centre /= static_cast<double>(cut.size());
    const Eigen::Vector3d u = normal.unitOrthogonal(), w = normal.cross(u);
    std::vector<std::pair<double, int>> ring;
    for (const auto& [edge, v] : cut) {
        const Eigen::Vector3d r = out.vertices[v] - centre;
        ring.emplace_back(pmath::atan2(r.dot(w), r.dot(u)), v);
    }
    std::sort(ring.begin(), ring.end());
    const int c = static_cast<int>(out.vertices.size());
    out.vertices.push_back(centre);
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const int a = ring[k].second, b = ring[(k + 1) % ring.size()].second;
        if (side > 0.0)
            out.triangles.push_back({c, b, a});
        else
            out.triangles.push_back({c, a, b});
    }
    return out;
}

}  // namespace

std::pair<TriangleMesh, TriangleMesh> splitConvexMesh(const TriangleMesh& mesh, const Eigen::Vector3d& point,
                                                      const Eigen::Vector3d& normal) {
    const std::string name = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (!(normal.norm() > 0.0) || !normal.allFinite() || !point.allFinite())
        throw Error(name + ": plane split needs a finite point and a non-zero normal");
    if (mesh.vertices.empty()) return {};
    const Eigen::Vector3d n = normal.normalized();
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double size = (hi - lo).norm();
    Eigen::Vector3d p = point;
    std::vector<double> distance(mesh.vertices.size());
    for (int attempt = 0;; ++attempt) {
        double closest = INFINITY;
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            distance[v] = n.dot(mesh.vertices[v] - p);
            closest = std::min(closest, std::abs(distance[v]));
        }
        if (closest > 1e-9 * size || attempt == 8) break;
        p += 1e-6 * size * n;
        logf(LogLevel::Debug, name, ": split plane moved by ", 1e-6 * size, " m off a vertex");
    }
    const bool anyPositive = std::any_of(distance.begin(), distance.end(), [](double d) { return d > 0.0; });
    const bool anyNegative = std::any_of(distance.begin(), distance.end(), [](double d) { return d <= 0.0; });
    if (!anyPositive) return {TriangleMesh{{}, {}, name + "+"}, mesh};
    if (!anyNegative) return {mesh, TriangleMesh{{}, {}, name + "-"}};
    return {half(mesh, distance, 1.0, n, name + "+"), half(mesh, distance, -1.0, n, name + "-")};
}

PlaneSplitFractureEngine::PlaneSplitFractureEngine(const FragmentSettings& settings) : settings_(settings) {
    settings_.validate();
}

void PlaneSplitFractureEngine::ensureState(btFractureRigidBody& body, FractureStatistics& stats) const {
    if (dynamic_cast<PlaneSplitState*>(body.fractureState())) return;
    if (!isConvex(body.mesh()))
        throw Error(body.name() + ": PlaneSplitFractureEngine splits convex bodies only");
    body.setFractureState(std::make_unique<PlaneSplitState>(body.mesh()));
    ++stats.bemBuilds;
}

FractureOutcome PlaneSplitFractureEngine::fracture(btFractureRigidBody& body,
                                                   const std::vector<BodyContact>& contacts,
                                                   FractureStatistics& stats) {
    if (contacts.empty()) return {};
    Timer timer;
    ensureState(body, stats);
    const double stateSeconds = timer.seconds();
    // The hardest impact: resting contacts (floored approach speed) have tiny Hertz peak forces.
    const BodyContact* impact = &contacts.front();
    for (const BodyContact& c : contacts)
        if (c.peakForce > impact->peakForce) impact = &c;
    const Eigen::Vector3d direction = impact->direction.normalized();
    int axis = 0;
    direction.cwiseAbs().minCoeff(&axis);
    timer.restart();
    FractureOutcome outcome = split(body, impact->point, direction.cross(Eigen::Vector3d::Unit(axis)));
    outcome.timings.bem = stateSeconds;  // the stand-in's "BEM": building its balancer
    outcome.timings.geometry = timer.seconds();
    return outcome;
}

FractureOutcome PlaneSplitFractureEngine::split(const btFractureRigidBody& body, const Eigen::Vector3d& point,
                                                const Eigen::Vector3d& normal) const {
    auto [positive, negative] = splitConvexMesh(body.mesh(), point, normal);
    if (positive.triangles.empty() || negative.triangles.empty()) return {};

    FractureOutcome outcome;
    for (TriangleMesh* piece : {&positive, &negative}) {
        const MassProperties mp = computeMassProperties(*piece);
        FragmentSpec spec;
        spec.volume = mp.volume;
        spec.centreOfMass = mp.centreOfMass;
        spec.inertiaAboutCom = body.material().density() * mp.inertiaPerDensity;
        spec.cls =
            fragmentSpecClass(classifyFragment(mp.volume, body.volume(), body.originalVolume(), settings_));
        spec.collisionMesh = std::move(*piece);
        outcome.fragments.push_back(std::move(spec));
    }
    return outcome;
}

}  // namespace btfracture
