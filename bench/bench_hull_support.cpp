// SPDX-License-Identifier: Zlib
// Support-query cost of fragment hulls: GraphHullShape's corner walk against Bullet's scan
// (btConvexHullShape), on hulls of 100, 500 and 2,000 corners (points on a flattened
// ellipsoid, 1 x 0.6 x 0.3, as chips and slabs are) and three query streams:
//  - random: independent directions (a cold start every query);
//  - coherent: each direction turned by about 0.05 rad from the last (GJK's iterations, one
//    pair's queries from step to step);
//  - alternating: two coherent streams interleaved, one near +d and one near -d (a fragment
//    in contact with two others, resting on the ground and touched from above).
// Each stream runs five times; the fastest run counts. Prints
// METRIC hull_support_ns_<stream>_<corners> (graph walk) and
// METRIC hull_scan_ns_<stream>_<corners> (Bullet's scan), both in ns per query.
//
// Usage: bench_hull_support [--queries N] [--stream NAME] [--corners N]
//   --queries N   queries per stream and hull (default 200,000)
//   --stream NAME only this stream; --corners N: only the hull of N corners (at least 24)
#include <btFracture/core/Timer.h>
#include <btFracture/dynamics/GraphHullShape.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

// `count` points on the ellipsoid with semi-axes 1, 0.6, 0.3 (all of them hull corners).
std::vector<btVector3> ellipsoidPoints(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    std::vector<btVector3> points;
    for (int i = 0; i < count; ++i) {
        btVector3 p(btScalar(normal(rng)), btScalar(normal(rng)), btScalar(normal(rng)));
        p.normalize();
        points.emplace_back(p.x(), btScalar(0.6) * p.y(), btScalar(0.3) * p.z());
    }
    return points;
}

// The query directions of `stream` ("random", "coherent" or "alternating").
std::vector<btVector3> queryStream(const std::string& stream, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    auto gaussian = [&] {
        return btVector3(btScalar(normal(rng)), btScalar(normal(rng)), btScalar(normal(rng)));
    };
    std::vector<btVector3> directions;
    btVector3 a = gaussian().normalized(), b = -a;
    for (int i = 0; i < count; ++i) {
        if (stream == "random") {
            directions.push_back(gaussian());
            continue;
        }
        btVector3& d = (stream == "alternating" && i % 2) ? b : a;
        d = (d + btScalar(0.05) * gaussian()).normalized();
        directions.push_back(d);
    }
    return directions;
}

// Fastest of five passes over `directions`, in ns per query; `checksum` sums the answers.
double nsPerQuery(const btConvexHullShape& shape, const std::vector<btVector3>& directions,
                  double& checksum) {
    double fastest = 1e30;
    for (int pass = 0; pass < 5; ++pass) {
        Timer timer;
        btVector3 sum(0, 0, 0);
        for (const btVector3& d : directions) sum += shape.localGetSupportingVertexWithoutMargin(d);
        fastest = std::min(fastest, timer.seconds());
        checksum = double(sum.x() + sum.y() + sum.z());
    }
    return fastest * 1e9 / double(directions.size());
}

}  // namespace

int main(int argc, char** argv) {
    int queries = 200000;
    std::vector<int> hulls = {100, 500, 2000};
    std::vector<std::string> streams = {"random", "coherent", "alternating"};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--queries" && hasValue && std::atoi(argv[i + 1]) > 0) {
            queries = std::atoi(argv[++i]);
        } else if (arg == "--corners" && hasValue && std::atoi(argv[i + 1]) >= 24) {
            hulls = {std::atoi(argv[++i])};
        } else if (arg == "--stream" && hasValue &&
                   (std::strcmp(argv[i + 1], "random") == 0 || std::strcmp(argv[i + 1], "coherent") == 0 ||
                    std::strcmp(argv[i + 1], "alternating") == 0)) {
            streams = {argv[++i]};
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
    if (mismatches) {
        std::fprintf(stderr, "bench_hull_support: %d streams where the walk and the scan disagree\n",
                     mismatches);
        return 1;
    }
    return 0;
}
