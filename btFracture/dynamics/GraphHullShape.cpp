// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/GraphHullShape.h>

#include <btFracture/core/Error.h>
#include <btFracture/geometry/ConvexHull.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

namespace btfracture {
namespace {

// Below this many corners a scan is as fast as a walk.
constexpr int kMinGraphCorners = 24;
// A corner within this fraction of |direction| x the hull's size of the best corner's value
// counts as a near tie (far above the rounding of a dot product of either precision).
constexpr double kTieMargin = std::is_same_v<btScalar, double> ? 1e-12 : 1e-5;
// Near-tie sets larger than this are resolved by a scan.
constexpr int kMaxPlateau = 12;

}  // namespace

GraphHullShape::GraphHullShape(const btScalar* points, int count, int stride)
    : btConvexHullShape(points, count, stride) {
    m_shapeType = CUSTOM_POLYHEDRAL_SHAPE_TYPE;
    const int n = getNumPoints();
    if (n < kMinGraphCorners) return;
    const btVector3* p = getUnscaledPoints();
    std::vector<Eigen::Vector3d> eigenPoints;
    eigenPoints.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        eigenPoints.emplace_back(p[i].x(), p[i].y(), p[i].z());
        size_ = std::max(size_, p[i].length());
    }
    TriangleMesh hull;
    try {
        hull = convexHullMesh(eigenPoints, "GraphHullShape");
    } catch (const Error&) {
        return;  // flat or degenerate: scan
    }
    // Corners are input points, exactly; each maps to the first point with its coordinates.
    std::map<std::array<double, 3>, int> firstIndex;
    for (int i = 0; i < n; ++i) firstIndex.emplace(std::array<double, 3>{p[i].x(), p[i].y(), p[i].z()}, i);
    const int corners = static_cast<int>(hull.vertices.size());
    pointIndex_.resize(static_cast<std::size_t>(corners));
    for (int c = 0; c < corners; ++c) {
        const auto& v = hull.vertices[static_cast<std::size_t>(c)];
        const auto found = firstIndex.find({v.x(), v.y(), v.z()});
        if (found == firstIndex.end()) {
            pointIndex_.clear();
            return;
        }
        pointIndex_[static_cast<std::size_t>(c)] = found->second;
    }
    corners_.resize(corners);
    for (int c = 0; c < corners; ++c) corners_[c] = p[pointIndex_[static_cast<std::size_t>(c)]];
    // Points that are not corners (inside, or on a face or edge up to the hull's snapping) can
    // tie with a corner: each is kept with its nearest corner.
    std::vector<char> isCorner(static_cast<std::size_t>(n), 0);
    for (const int i : pointIndex_) isCorner[static_cast<std::size_t>(i)] = 1;
    std::vector<std::vector<int>> shadows(static_cast<std::size_t>(corners));
    for (const auto& [coordinates, i] : firstIndex) {
        if (isCorner[static_cast<std::size_t>(i)]) continue;
        int nearest = 0;
        for (int c = 1; c < corners; ++c)
            if ((corners_[c] - p[i]).length2() < (corners_[nearest] - p[i]).length2()) nearest = c;
        shadows[static_cast<std::size_t>(nearest)].push_back(i);
        extras_.push_back(i);
    }
    std::sort(extras_.begin(), extras_.end());
    shadowOffsets_.assign(1, 0);
    for (auto& list : shadows) {
        std::sort(list.begin(), list.end());
        shadowPoints_.insert(shadowPoints_.end(), list.begin(), list.end());
        shadowOffsets_.push_back(static_cast<int>(shadowPoints_.size()));
    }
    std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(corners));
    for (const auto& t : hull.triangles)
        for (int e = 0; e < 3; ++e) {
            adjacent[static_cast<std::size_t>(t[e])].push_back(t[(e + 1) % 3]);
            adjacent[static_cast<std::size_t>(t[(e + 1) % 3])].push_back(t[e]);
        }
    offsets_.assign(1, 0);
    for (auto& list : adjacent) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        neighbours_.insert(neighbours_.end(), list.begin(), list.end());
        offsets_.push_back(static_cast<int>(neighbours_.size()));
    }
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = 0; sign < 2; ++sign) {
            int best = 0;
            for (int c = 1; c < corners; ++c)
                if (sign == 0 ? corners_[c][axis] > corners_[best][axis]
                              : corners_[c][axis] < corners_[best][axis])
                    best = c;
            axisExtreme_[2 * axis + sign] = best;
        }
}

int GraphHullShape::climb(const btVector3& d) const {
    if (offsets_.empty()) return -1;
    const btVector3* p = getUnscaledPoints();
    auto value = [&](int c) { return corners_[c].dot(d); };
    const int axis = d.closestAxis();
    int v = axisExtreme_[2 * axis + (d[axis] < 0 ? 1 : 0)];
    btScalar best = value(v);
    const int cached = last_.load(std::memory_order_relaxed);
    if (cached != v) {
        const btScalar c = value(cached);
        if (c > best) v = cached, best = c;
    }
    btScalar runnerUp;
    for (;;) {
        int next = v;
        btScalar nextValue = best;
        runnerUp = -std::numeric_limits<btScalar>::infinity();
        for (int k = offsets_[static_cast<std::size_t>(v)]; k < offsets_[static_cast<std::size_t>(v) + 1];
             ++k) {
            const int u = neighbours_[static_cast<std::size_t>(k)];
            const btScalar f = value(u);
            runnerUp = std::max(runnerUp, f);
            if (f > nextValue) next = u, nextValue = f;
        }
        if (next == v) break;
        v = next, best = nextValue;
    }
    // Bullet's scan keeps the largest value, the first index among equal ones.
    int bestPoint = pointIndex_[static_cast<std::size_t>(v)];
    auto consider = [&](int point) {
        const btScalar f = p[point].dot(d);
        if (f > best || (f == best && point < bestPoint)) bestPoint = point, best = f;
    };
    const btScalar margin = btScalar(kTieMargin) * d.length() * size_;
    if (!(margin >= 0) || !(best == best)) return -1;  // non-finite direction
    if (best - margin > runnerUp) {
        for (int k = shadowOffsets_[static_cast<std::size_t>(v)];
             k < shadowOffsets_[static_cast<std::size_t>(v) + 1]; ++k)
            consider(shadowPoints_[static_cast<std::size_t>(k)]);
    } else {
        // Near tie: every corner within the margin of the best (a connected part of the graph
        // around v) and every point that is not a corner.
        const btScalar floor = best - margin;
        std::array<int, kMaxPlateau> plateau;
        int size = 0;
        plateau[size++] = v;
        for (int i = 0; i < size; ++i) {
            const int c = plateau[static_cast<std::size_t>(i)];
            for (int k = offsets_[static_cast<std::size_t>(c)]; k < offsets_[static_cast<std::size_t>(c) + 1];
                 ++k) {
                const int u = neighbours_[static_cast<std::size_t>(k)];
                if (value(u) < floor ||
                    std::find(plateau.begin(), plateau.begin() + size, u) != plateau.begin() + size)
                    continue;
                if (size == kMaxPlateau) return -1;
                plateau[static_cast<std::size_t>(size++)] = u;
            }
        }
        for (int i = 0; i < size; ++i)
            consider(pointIndex_[static_cast<std::size_t>(plateau[static_cast<std::size_t>(i)])]);
        for (const int e : extras_) consider(e);
    }
    last_.store(v, std::memory_order_relaxed);
    return bestPoint;
}

btVector3 GraphHullShape::localGetSupportingVertexWithoutMargin(const btVector3& direction) const {
    const int index = climb(direction * m_localScaling);
    if (index < 0) return btConvexHullShape::localGetSupportingVertexWithoutMargin(direction);
    return getUnscaledPoints()[index] * m_localScaling;
}

void GraphHullShape::batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* directions,
                                                                       btVector3* out, int count) const {
    for (int i = 0; i < count; ++i) {
        const btVector3 d = directions[i] * m_localScaling;
        const int index = climb(d);
        if (index < 0) {
            btConvexHullShape::batchedUnitVectorGetSupportingVertexWithoutMargin(directions + i, out + i, 1);
            continue;
        }
        out[i] = getUnscaledPoints()[index] * m_localScaling;
        out[i][3] = getUnscaledPoints()[index].dot(d);  // Bullet's: w holds the support value
    }
}

const char* GraphHullShape::serialize(void* dataBuffer, btSerializer* serializer) const {
    const char* structName = btConvexHullShape::serialize(dataBuffer, serializer);
    static_cast<btConvexHullShapeData*>(dataBuffer)
        ->m_convexInternalShapeData.m_collisionShapeData.m_shapeType = CONVEX_HULL_SHAPE_PROXYTYPE;
    return structName;
}

}  // namespace btfracture
