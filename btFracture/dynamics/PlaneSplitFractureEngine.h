// SPDX-License-Identifier: Zlib
#pragma once
// A stand-in FractureEngine for tests of the coupling alone: it cuts a convex body in two by a
// plane through the impact point. No stresses, no cracks: whenever the world calls it (impulse
// sum over the body's threshold), the body splits.
//
//  - impact point p and direction d are those of the contact with the largest Hertz peak force
//    (the hardest impact; resting contacts, e.g. on the ground, have tiny peak forces);
//  - the cut plane contains p and d; its normal is d x e, e the body axis least aligned with d
//    (lowest index on ties), so a slab hit on its face splits across its thinnest direction;
//  - halves are exact closed meshes (Sutherland-Hodgman per triangle, the cap fanned around its
//    centroid) and their mass properties are exact polyhedral integrals (MassProperties.h);
//  - classes follow §5.2 (classifyFragment with the settings' volume fractions);
//  - per body it builds a TractionBalancer (Eq. 6) on first use as its FractureState and counts
//    that as one "BEM build" in FractureStatistics::bemBuilds, to exercise the lazy state path;
//    the > 95 % fragment keeps that state, new breakable fragments start without one.
// Only convex bodies are supported (checked; a non-convex body throws btfracture::Error, which the
// world turns into an unbreakable body).
#include <btFracture/dynamics/FractureEngine.h>
#include <btFracture/geometry/FragmentClasses.h>

namespace btfracture {

class PlaneSplitFractureEngine : public FractureEngine {
public:
    explicit PlaneSplitFractureEngine(const FragmentSettings& settings = {});
    FractureOutcome fracture(btFractureRigidBody& body, const std::vector<BodyContact>& contacts,
                             FractureStatistics& stats) override;

protected:
    // The stand-in state on first use (counted as a BEM build); throws for a non-convex body.
    void ensureState(btFractureRigidBody& body, FractureStatistics& stats) const;
    // Both halves of `body` cut by the plane n.(x - p) = 0 (body frame), classified; empty when
    // the plane misses the body.
    FractureOutcome split(const btFractureRigidBody& body, const Eigen::Vector3d& p,
                          const Eigen::Vector3d& n) const;

private:
    FragmentSettings settings_;
};

// The two closed halves of a convex closed mesh cut by the plane n.(x - p) = 0; first the half on
// the positive side. A half is empty when the plane misses the mesh. Vertices within a relative
// 1e-9 of the plane move it by 1e-6 of the mesh size along n (logged).
std::pair<TriangleMesh, TriangleMesh> splitConvexMesh(const TriangleMesh& mesh, const Eigen::Vector3d& p,
                                                      const Eigen::Vector3d& n);

}  // namespace btfracture
