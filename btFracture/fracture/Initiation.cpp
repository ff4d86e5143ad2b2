// SPDX-License-Identifier: Zlib
#include <btFracture/fracture/Initiation.h>

#include <btFracture/core/Log.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/fracture/CrackSeed.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace btfracture {
namespace {

constexpr int kSeedHalvings = 2;  // smallest seed: a quarter of seedRadius x h
constexpr int kSurfaceSeedRings = 2;

double distanceToFront(const CrackMesh& cracks, const Eigen::Vector3d& x) {
    double best = INFINITY;
    for (const auto& e : cracks.frontEdges())
        best = std::min({best, (cracks.node(e.a) - x).norm(), (cracks.node(e.b) - x).norm()});
    return best;
}

// A two-ring half-disc of radius r on the surface point x (addHalfDiscCrack), its diameter's
// nodes moved onto the surface (each by at most kSeedMouthSag r, the sag of a curved face) so
// that they are matched to it as mouth nodes, its arc inside the body. Adds it to `cracks` and
// returns true when it fits; leaves `cracks` as it was otherwise.
bool addSurfaceSeed(CrackMesh& cracks, const SurfaceMesh& mesh, const Eigen::Vector3d& x,
                    const Eigen::Vector3d& crackNormal, const Eigen::Vector3d& inward, double r) {
    // Two rings, not one: a one-ring half-disc has a single opening unknown (its centre), so every
    // front node gets the same K_I and its ends do not run along the surface. Semicircular crack
    // (bench_sif_validation's plate): one ring K_I deepest +4.3 % of Newman & Raju and next to the
    // face / deepest 1.00; two rings +0.4 % and 1.13 (Newman & Raju: 1.12).
    CrackMesh disc;
    addHalfDiscCrack(disc, x, crackNormal, inward, r, kSurfaceSeedRings);
    std::vector<Eigen::Vector3d> nodes;
    for (int i = 0; i < disc.nodeCount(); ++i) {
        const Eigen::Vector3d& p = disc.node(i);
        const bool onDiameter = std::abs((p - x).dot(inward)) <= 1e-9 * r;
        if (!onDiameter) {
            if (!mesh.encloses(p)) return false;
            nodes.push_back(p);
            continue;
        }
        const SurfaceMesh::Nearest nearest = mesh.nearest(p);
        if (nearest.distance > kSeedMouthSag * r) return false;
        nodes.push_back(nearest.point);
    }
    const int first = cracks.nodeCount();
    for (const Eigen::Vector3d& p : nodes) cracks.addNode(p);
    for (int t = 0; t < disc.triangleCount(); ++t) {
        const auto& tri = disc.triangle(t);
        cracks.addTriangle(first + tri[0], first + tri[1], first + tri[2]);
    }
    return true;
}

}  // namespace

std::vector<SeedCandidate> findSeedCandidates(const SurfaceMesh& mesh,
                                              const std::vector<Eigen::Matrix3d>& stresses,
                                              const MaterialField& field, const CrackMesh& cracks,
                                              const std::vector<char>& blocked) {
    const double factor = field.material().compressiveFactor();
    std::vector<SeedCandidate> out;
    for (int t = 0; t < mesh.triangleCount(); ++t) {
        if (blocked[t]) continue;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(stresses[t]);
        const double strength = field.tensileStrength(mesh.centroid(t));
        const double tensile = eig.eigenvalues()[2] / strength;
        const double compressive = -eig.eigenvalues()[0] / (factor * strength);
        if (std::max(tensile, compressive) <= 1.0) continue;
        if (distanceToFront(cracks, mesh.centroid(t)) < mesh.diameter(t)) continue;
        SeedCandidate c;
        c.triangle = t;
        c.compressive = compressive > tensile;
        c.excess = std::max(tensile, compressive);
        c.crackNormal = eig.eigenvectors().col(c.compressive ? 0 : 2);
        out.push_back(c);
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const SeedCandidate& a, const SeedCandidate& b) { return a.excess > b.excess; });
    return out;
}

int seedCracks(CrackMesh& cracks, const SurfaceMesh& mesh, const std::vector<SeedCandidate>& candidates,
               int maxSeeds, double seedRadius, double elementSize, SeedShape shape,
               std::vector<char>& blocked) {
    int seeds = 0;
    std::vector<Eigen::Vector3d> seededAt;
    for (const SeedCandidate& c : candidates) {
        if (seeds >= maxSeeds) break;
        const Eigen::Vector3d& surfaceNormal = mesh.normal(c.triangle);
        const Eigen::Vector3d x = mesh.centroid(c.triangle);
        const double h = mesh.diameter(c.triangle);
        if (std::any_of(seededAt.begin(), seededAt.end(),
                        [&](const Eigen::Vector3d& p) { return (p - x).norm() < h; }))
            continue;
        // Inward direction within the crack plane.
        Eigen::Vector3d inward = -(surfaceNormal - surfaceNormal.dot(c.crackNormal) * c.crackNormal);
        if (inward.norm() < 0.3) {  // crack plane within ~17 degrees of the surface: no seed
            logf(LogLevel::Debug, "initiation: triangle ", c.triangle,
                 " skipped, crack plane parallel to the surface");
            continue;
        }
        inward.normalize();
        // Rotate the hexagon so that one vertex points at the surface point.
        const Eigen::Vector3d u = c.crackNormal.unitOrthogonal(), v = c.crackNormal.cross(u);
        const double rotation = pmath::atan2((-inward).dot(v), (-inward).dot(u));
        // Near an edge or in a thin wall the full seed pokes out of the body: halve it (twice at
        // most) rather than lose the most loaded spot, which on a box's edge or a bowl's wall is
        // where glass breaks.
        CrackMesh trial;
        bool inside = false;
        double r = seedRadius * (elementSize > 0.0 ? elementSize : h);
        for (int halving = 0; halving <= kSeedHalvings && !inside; ++halving, r *= 0.5) {
            trial = cracks;
            if (shape == SeedShape::SurfaceBreaking) {
                inside = addSurfaceSeed(trial, mesh, x, c.crackNormal, inward, r);
            } else {
                addDiscCrack(trial, x + (1.05 * r) * inward, c.crackNormal, r, 1, rotation);
                inside = true;
                for (int i = cracks.nodeCount(); i < trial.nodeCount() && inside; ++i)
                    inside = mesh.encloses(trial.node(i));
            }
            if (inside && halving > 0)
                logf(LogLevel::Debug, "initiation: triangle ", c.triangle, " seeded at 1/", 1 << halving,
                     " of the seed radius (a full seed would leave the body)");
        }
        if (!inside) {
            logf(LogLevel::Debug, "initiation: triangle ", c.triangle, " skipped, a seed of 1/",
                 1 << kSeedHalvings, " of the radius would still leave the body");
            continue;
        }
        cracks = std::move(trial);
        blocked[c.triangle] = 1;
        seededAt.push_back(x);
        ++seeds;
    }
    return seeds;
}

}  // namespace btfracture
