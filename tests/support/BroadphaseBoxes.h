// SPDX-License-Identifier: Zlib
#pragma once
// Whether two bodies' broadphase boxes overlap, by the broadphase's own test (btDbvtBroadphase
// pairs exactly the bodies whose boxes pass it).
#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <LinearMath/btAabbUtil2.h>

namespace btfracture::test {

inline bool boxesOverlap(const btBroadphaseProxy& a, const btBroadphaseProxy& b) {
    return TestAabbAgainstAabb2(a.m_aabbMin, a.m_aabbMax, b.m_aabbMin, b.m_aabbMax);
}

}  // namespace btfracture::test
