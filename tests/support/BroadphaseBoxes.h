// SPDX-License-Identifier: Zlib
#pragma once
// Whether two bodies' broadphase boxes overlap (the proxies' boxes, padded but without the
// margin btDbvtBroadphase adds to its tree leaves, by which it pairs bodies), by Bullet's own box
// test (btAabbUtil2.h).
#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <LinearMath/btAabbUtil2.h>

namespace btfracture::test {

inline bool boxesOverlap(const btBroadphaseProxy& a, const btBroadphaseProxy& b) {
    return TestAabbAgainstAabb2(a.m_aabbMin, a.m_aabbMax, b.m_aabbMin, b.m_aabbMax);
}

}  // namespace btfracture::test
