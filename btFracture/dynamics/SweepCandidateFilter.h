// SPDX-License-Identifier: Zlib
#pragma once
// Bullet's CCD sweeps (motion clamping in integrateTransforms, predictive contacts) cast a sphere
// of the body's swept-sphere radius r along its step, from its origin to origin + v dt, against
// every body whose broadphase leaf the path crosses; the leaves are widened by 5 cm
// (DBVT_BP_MARGIN), so among centimetre chips most candidates lie far from the path and each
// costs a conservative-advancement query. A candidate can only be hit where the sphere comes
// within the advancement's tolerance (1 mm) of its shape, margins included; its shape lies inside
// its bounding sphere (centre c, radius R, at its current transform), so a candidate with
//     distance(c, path) > r + R + tolerance
// cannot be hit and is left out; so is a convex candidate whose support plane along the unit
// vector n from c to the path's nearest point lies more than the tolerance below the sphere's
// lowest reach along n, min(from.n, to.n) - r (one support query instead of an advancement).
// The sweep finds the same hit, or none, as without the filter.
// While a SweepCandidateFilter is alive, it is the pair cache's overlap filter, which Bullet's
// sweep callback asks about each candidate; the test the cache would otherwise make (a filter
// installed before, else the collision groups and masks) comes first.
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>

namespace btfracture {

class SweepCandidateFilter : public btOverlapFilterCallback {
public:
    // Installs itself on `cache` for sweeps over a step of `timeStep` [s]; the destructor puts
    // back the filter that was there.
    SweepCandidateFilter(btOverlappingPairCache& cache, btScalar timeStep);
    ~SweepCandidateFilter() override;
    SweepCandidateFilter(const SweepCandidateFilter&) = delete;
    SweepCandidateFilter& operator=(const SweepCandidateFilter&) = delete;

    // proxy0: the candidate, proxy1: the swept body (Bullet's argument order in its sweep callback).
    bool needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const override;

    // Calls to needBroadphaseCollision, candidates left out, and those of them left out by the
    // support plane (their bounding spheres reach the path).
    long long queries() const { return queries_; }
    long long rejected() const { return rejected_; }
    long long rejectedBySupport() const { return rejectedBySupport_; }

private:
    btOverlappingPairCache& cache_;
    btOverlapFilterCallback* previous_;
    btScalar timeStep_;
    mutable long long queries_ = 0, rejected_ = 0, rejectedBySupport_ = 0;
};

}  // namespace btfracture
