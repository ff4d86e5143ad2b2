// SPDX-License-Identifier: Zlib
#pragma once
// Bullet's perturbed multi-point contact generation for the collision pairs created while a
// NewPairMultipoint is alive (the new fragments' pairs in the replayed step), for their first
// kPerturbedSteps narrowphase calls: a fragment resting on something starts with a full contact
// manifold instead of one point per step (which lets it sink and tip: popping). Afterwards a pair
// of two moving bodies continues on the same manifold with the configuration's own settings, so
// neighbours that stay apart do not pay three extra GJK queries per step for the rest of their
// lives; a pair with static or kinematic geometry (the ground) keeps perturbing. A convex pair on
// its own manifold skips the calls that cannot find a contact (SeparatedPairCache), in either
// phase.
// Covered: the shape pairs that use the configuration's convex-convex and convex-plane create
// functions of convex hulls (in Bullet's default configuration every convex pair without a
// special algorithm, boxes included); configurations whose functions are not Bullet's are left
// alone.
#include <memory>

class btCollisionConfiguration;
class btCollisionDispatcher;

namespace btfracture {

class NewPairMultipoint {
public:
    static constexpr int kPerturbedSteps = 10;                 // 40 ms at 250 Hz
    static constexpr int kIterations = 3, kMinimumPoints = 3;  // btDefaultCollisionConfiguration's suggestion

    // Registers the phased create functions with `dispatcher`; the destructor puts back those
    // of `configuration`. Algorithms created meanwhile outlive this object.
    NewPairMultipoint(btCollisionDispatcher& dispatcher, btCollisionConfiguration& configuration);
    ~NewPairMultipoint();
    NewPairMultipoint(const NewPairMultipoint&) = delete;
    NewPairMultipoint& operator=(const NewPairMultipoint&) = delete;

private:
    struct Registered;
    btCollisionDispatcher& dispatcher_;
    std::unique_ptr<Registered> registered_;
};

}  // namespace btfracture
