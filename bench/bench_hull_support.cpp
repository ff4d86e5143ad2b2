// SPDX-License-Identifier: Zlib
// Support-query cost of fragment hulls: GraphHullShape's corner walk against Bullet's scan
// (btConvexHullShape), on hulls of 100, 500 and 2,000 corners (points on a flattened
// ellipsoid, 1 x 0.6 x 0.3, as chips and slabs are) and three query streams:
//  - random: independent directions (a cold start every query);
//  - coherent: each direction turned by about 0.05 rad from the last (GJK's iterations, one
//    pair's queries from step to step);
//  - alternating: two coherent streams interleaved, one near +d and one near -d (a fragment
//    in contact with two others, resting on the ground and touched from above);
//  - heap: 600 hulls of 150 corners (sizes 0.2-1), each query on a hull picked at random with
//    that hull's own coherent stream: a heap of chips, whose corners are not in cache.
// Each stream runs five times; the fastest run counts. Prints
// METRIC hull_support_ns_<stream>_<corners> (graph walk) and
// METRIC hull_scan_ns_<stream>_<corners> (Bullet's scan), both in ns per query, and
// METRIC hull_support_ns_heap_600x150 / hull_scan_ns_heap_600x150.
//
// Usage: bench_hull_support [--queries N] [--stream NAME] [--corners N]
//   --queries N   queries per stream and hull (default 200,000)
//   --stream NAME only this stream; --corners N: only the hull of N corners (at least 24);
//                 either one leaves out the heap
#include "BestOf.h"

#include <btFracture/dynamics/GraphHullShape.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

// A vector of three standard normal components (its direction is uniform on the sphere).
btVector3 gaussianVector(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    const double x = normal(rng), y = normal(rng), z = normal(rng);
    return btVector3(btScalar(x), btScalar(y), btScalar(z));
}

// `count` points on the ellipsoid with semi-axes 1, 0.6, 0.3 (all of them hull corners).
std::vector<btVector3> ellipsoidPoints(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<btVector3> points;
    for (int i = 0; i < count; ++i) {
        const btVector3 p = gaussianVector(rng).normalized();
        points.emplace_back(p.x(), btScalar(0.6) * p.y(), btScalar(0.3) * p.z());
    }
    return points;
}

// `d` turned by about 0.05 rad in a random direction (a coherent stream's next query).
btVector3 turned(const btVector3& d, std::mt19937& rng) {
    return (d + btScalar(0.05) * gaussianVector(rng)).normalized();
}

// The query directions of `stream` ("random", "coherent" or "alternating").
std::vector<btVector3> queryStream(const std::string& stream, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<btVector3> directions;
    btVector3 a = gaussianVector(rng).normalized(), b = -a;
    for (int i = 0; i < count; ++i) {
        if (stream == "random") {
            directions.push_back(gaussianVector(rng));
            continue;
        }
        btVector3& d = (stream == "alternating" && i % 2) ? b : a;
        d = turned(d, rng);
        directions.push_back(d);
    }
    return directions;
}

// Fastest of five passes over `directions`, in ns per query; `checksum` sums the answers.
double nsPerQuery(const btConvexHullShape& shape, const std::vector<btVector3>& directions,
                  double& checksum) {
    const double seconds = bestOf(5, [&] {
        btVector3 sum(0, 0, 0);
        for (const btVector3& d : directions) sum += shape.localGetSupportingVertexWithoutMargin(d);
        checksum = double(sum.x() + sum.y() + sum.z());
    });
    return seconds * 1e9 / double(directions.size());
}

struct HeapQuery {
    int hull;
    btVector3 direction;
};

// The heap's query stream: a random hull per query, each hull's directions coherent.
std::vector<HeapQuery> heapStream(int hulls, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, hulls - 1);
    std::vector<btVector3> current;
    for (int h = 0; h < hulls; ++h) current.push_back(gaussianVector(rng).normalized());
    std::vector<HeapQuery> queries;
    for (int i = 0; i < count; ++i) {
        const int h = pick(rng);
        btVector3& d = current[static_cast<std::size_t>(h)];
        d = turned(d, rng);
        queries.push_back({h, d});
    }
    return queries;
}

// As nsPerQuery, over a heap of shapes.
template <class Shape>
double nsPerHeapQuery(const std::vector<std::unique_ptr<Shape>>& shapes,
                      const std::vector<HeapQuery>& queries, double& checksum) {
    const double seconds = bestOf(5, [&] {
        btVector3 sum(0, 0, 0);
        for (const HeapQuery& q : queries)
            sum +=
                shapes[static_cast<std::size_t>(q.hull)]->localGetSupportingVertexWithoutMargin(q.direction);
        checksum = double(sum.x() + sum.y() + sum.z());
    });
    return seconds * 1e9 / double(queries.size());
}

}  // namespace

int main(int argc, char** argv) {
    int queries = 200000;
    std::vector<int> hulls = {100, 500, 2000};
    std::vector<std::string> streams = {"random", "coherent", "alternating"};
    bool heap = true;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--queries" && hasValue && std::atoi(argv[i + 1]) > 0) {
            queries = std::atoi(argv[++i]);
        } else if (arg == "--corners" && hasValue && std::atoi(argv[i + 1]) >= 24) {
            hulls = {std::atoi(argv[++i])};
            heap = false;
        } else if (arg == "--stream" && hasValue &&
                   (std::strcmp(argv[i + 1], "random") == 0 || std::strcmp(argv[i + 1], "coherent") == 0 ||
                    std::strcmp(argv[i + 1], "alternating") == 0)) {
            streams = {argv[++i]};
            heap = false;
        } else {
            std::fprintf(stderr,
                         "bench_hull_support: unknown or incomplete argument '%s'\n"
                         "usage: bench_hull_support [--queries N] [--stream random|coherent|alternating]"
                         " [--corners N>=24]\n",
                         argv[i]);
            return 2;
        }
    }
    int mismatches = 0;
    for (const int corners : hulls) {
        const std::vector<btVector3> points = ellipsoidPoints(corners, 7u + unsigned(corners));
        const GraphHullShape graph(&points[0].x(), corners, sizeof(btVector3));
        const btConvexHullShape scan(&points[0].x(), corners, sizeof(btVector3));
        for (const std::string& stream : streams) {
            const std::vector<btVector3> directions = queryStream(stream, queries, 11u + unsigned(corners));
            double graphSum = 0, scanSum = 0;
            const double graphNs = nsPerQuery(graph, directions, graphSum);
            const double scanNs = nsPerQuery(scan, directions, scanSum);
            if (graphSum != scanSum) ++mismatches;
            std::printf("METRIC hull_support_ns_%s_%d %.1f ns\n", stream.c_str(), corners, graphNs);
            std::printf("METRIC hull_scan_ns_%s_%d %.1f ns\n", stream.c_str(), corners, scanNs);
        }
    }
    if (heap) {
        constexpr int kHeapHulls = 600, kHeapCorners = 150;
        std::vector<std::unique_ptr<GraphHullShape>> graphs;
        std::vector<std::unique_ptr<btConvexHullShape>> scans;
        for (int h = 0; h < kHeapHulls; ++h) {
            std::vector<btVector3> points = ellipsoidPoints(kHeapCorners, 1000u + unsigned(h));
            const btScalar size = btScalar(0.2 + 0.8 * h / (kHeapHulls - 1));
            for (btVector3& p : points) p *= size;
            graphs.push_back(
                std::make_unique<GraphHullShape>(&points[0].x(), kHeapCorners, sizeof(btVector3)));
            scans.push_back(
                std::make_unique<btConvexHullShape>(&points[0].x(), kHeapCorners, sizeof(btVector3)));
        }
        const std::vector<HeapQuery> heapQueries = heapStream(kHeapHulls, queries, 13u);
        double graphSum = 0, scanSum = 0;
        const double graphNs = nsPerHeapQuery(graphs, heapQueries, graphSum);
        const double scanNs = nsPerHeapQuery(scans, heapQueries, scanSum);
        if (graphSum != scanSum) ++mismatches;
        std::printf("METRIC hull_support_ns_heap_%dx%d %.1f ns\n", kHeapHulls, kHeapCorners, graphNs);
        std::printf("METRIC hull_scan_ns_heap_%dx%d %.1f ns\n", kHeapHulls, kHeapCorners, scanNs);
    }
    if (mismatches) {
        std::fprintf(stderr, "bench_hull_support: %d streams where the walk and the scan disagree\n",
                     mismatches);
        return 1;
    }
    return 0;
}
