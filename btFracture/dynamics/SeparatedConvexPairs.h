// SPDX-License-Identifier: Zlib
#pragma once
// Skips Bullet's convex-convex algorithm for pairs that cannot touch (SeparatedPairCache) while
// registered with a dispatcher: the configuration's convex-convex create function is wrapped for
// every shape pair that uses it. Covered: Bullet's btConvexConvexAlgorithm without perturbation
// (btDefaultCollisionConfiguration's default) on its own manifold; compound children (a manifold
// shared with the parent) and other configurations keep the configuration's algorithm.
#include <memory>

class btCollisionConfiguration;
class btCollisionDispatcher;

namespace btfracture {

class SeparatedConvexPairs {
public:
    // Registers the wrapped create functions with `dispatcher`; the destructor puts back those of
    // `configuration`. Algorithms created meanwhile outlive this object.
    SeparatedConvexPairs(btCollisionDispatcher& dispatcher, btCollisionConfiguration& configuration);
    ~SeparatedConvexPairs();
    SeparatedConvexPairs(const SeparatedConvexPairs&) = delete;
    SeparatedConvexPairs& operator=(const SeparatedConvexPairs&) = delete;

    // Registers the wrapped functions again (after something else registered its own).
    void install();

private:
    struct Registered;
    btCollisionDispatcher& dispatcher_;
    std::unique_ptr<Registered> registered_;
};

}  // namespace btfracture
