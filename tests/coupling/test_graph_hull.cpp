// SPDX-License-Identifier: Zlib
// GraphHullShape answers every support query with the point Bullet's scan over all points
// returns (btConvexHullShape), ties and points that are not corners included.
#include <btFracture/dynamics/GraphHullShape.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletFileLoader/btBulletFile.h>
#include <BulletWorldImporter/btBulletWorldImporter.h>
#include <LinearMath/btSerializer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace btfracture;

namespace {

// The point Bullet's scan returns and GraphHullShape's, bit for bit, for `direction`.
void expectSameSupport(const btConvexHullShape& scan, const GraphHullShape& graph,
                       const btVector3& direction) {
    const btVector3 a = scan.localGetSupportingVertexWithoutMargin(direction),
                    b = graph.localGetSupportingVertexWithoutMargin(direction);
    EXPECT_TRUE(a.x() == b.x() && a.y() == b.y() && a.z() == b.z())
        << "direction (" << direction.x() << ", " << direction.y() << ", " << direction.z() << "): scan ("
        << a.x() << ", " << a.y() << ", " << a.z() << "), graph (" << b.x() << ", " << b.y() << ", " << b.z()
        << ")";
}

// The shape of `points` (GraphHullShape, or btConvexHullShape for Bullet's scan).
template <class Shape>
Shape shapeOf(const std::vector<btVector3>& points) {
    return Shape(&points[0].x(), static_cast<int>(points.size()), sizeof(btVector3));
}

// `count` points uniform in [-1, 1]^3.
std::vector<btVector3> pointsInCube(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<btVector3> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(btScalar(uniform(rng)), btScalar(uniform(rng)), btScalar(uniform(rng)));
    return points;
}

// Directions that meet ties: the axes, the diagonals and every point's own direction.
std::vector<btVector3> probeDirections(const std::vector<btVector3>& points, std::mt19937& rng) {
    std::vector<btVector3> directions;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) directions.emplace_back(btScalar(x), btScalar(y), btScalar(z));
    for (const auto& p : points) directions.push_back(p);
    std::normal_distribution<double> normal;
    for (int i = 0; i < 2000; ++i)
        directions.emplace_back(btScalar(normal(rng)), btScalar(normal(rng)), btScalar(normal(rng)));
    return directions;
}

}  // namespace

TEST(GraphHullShape, SameSupportAsTheScanOnARoundHull) {
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    std::vector<btVector3> points;
    for (int i = 0; i < 400; ++i) {
        btVector3 p(btScalar(normal(rng)), btScalar(normal(rng)), btScalar(0.3 * normal(rng)));
        points.push_back(p.normalized() * btScalar(0.05));  // corners of a flattened sphere
    }
    const auto scan = shapeOf<btConvexHullShape>(points);
    const auto graph = shapeOf<GraphHullShape>(points);
    ASSERT_GT(graph.graphCorners(), 300);
    EXPECT_EQ(graph.getShapeType(), CUSTOM_POLYHEDRAL_SHAPE_TYPE);
    for (const auto& d : probeDirections(points, rng)) expectSameSupport(scan, graph, d);
}

// A box of 5 x 5 x 5 grid points: 8 corners, the other 117 points on faces, edges or inside,
// in shuffled order, with duplicates. Axis and diagonal directions tie whole faces and edges.
TEST(GraphHullShape, TiesResolveToTheScansFirstPoint) {
    std::mt19937 rng(11);
    std::vector<btVector3> points;
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 5; ++y)
            for (int z = 0; z < 5; ++z)
                points.emplace_back(btScalar(0.1 * x), btScalar(0.2 * y), btScalar(0.05 * z));
    for (int i = 0; i < 20; ++i) points.push_back(points[static_cast<std::size_t>(i * 6)]);
    std::shuffle(points.begin(), points.end(), rng);
    const auto scan = shapeOf<btConvexHullShape>(points);
    const auto graph = shapeOf<GraphHullShape>(points);
    ASSERT_EQ(graph.graphCorners(), 8);
    for (const auto& d : probeDirections(points, rng)) expectSameSupport(scan, graph, d);
    expectSameSupport(scan, graph, btVector3(0, 0, 0));
}

TEST(GraphHullShape, ScaledShapeAndBatchedQueries) {
    const std::vector<btVector3> points = pointsInCube(300, 3);
    std::mt19937 rng(13);
    auto scan = shapeOf<btConvexHullShape>(points);
    auto graph = shapeOf<GraphHullShape>(points);
    const btVector3 scaling(2.0, 0.5, 1.5);
    scan.setLocalScaling(scaling);
    graph.setLocalScaling(scaling);
    const std::vector<btVector3> directions = probeDirections(points, rng);
    for (const auto& d : directions) expectSameSupport(scan, graph, d);
    std::vector<btVector3> a(directions.size()), b(directions.size());
    scan.batchedUnitVectorGetSupportingVertexWithoutMargin(directions.data(), a.data(),
                                                           static_cast<int>(a.size()));
    graph.batchedUnitVectorGetSupportingVertexWithoutMargin(directions.data(), b.data(),
                                                            static_cast<int>(b.size()));
    for (std::size_t i = 0; i < directions.size(); ++i)
        for (int k = 0; k < 4; ++k) ASSERT_EQ(a[i][k], b[i][k]) << "direction " << i << ", lane " << k;
}

TEST(GraphHullShape, FewOrFlatPointsScan) {
    std::vector<btVector3> flat;
    for (int i = 0; i < 40; ++i)
        flat.emplace_back(btScalar(std::cos(0.3 * i)), btScalar(std::sin(0.3 * i)), btScalar(0));
    const auto graph = shapeOf<GraphHullShape>(flat);
    const auto scan = shapeOf<btConvexHullShape>(flat);
    EXPECT_EQ(graph.graphCorners(), 0);
    expectSameSupport(scan, graph, btVector3(0.3, 0.9, 0.1));
    const std::vector<btVector3> few(flat.begin(), flat.begin() + 6);
    const auto small = shapeOf<GraphHullShape>(few);
    EXPECT_EQ(small.graphCorners(), 0);
}

// A .bullet file holds it as a plain convex hull, with every point.
TEST(GraphHullShape, SerializedAsAConvexHull) {
    const std::vector<btVector3> points = pointsInCube(100, 5);
    auto graph = shapeOf<GraphHullShape>(points);
    btDefaultSerializer serializer;
    serializer.startSerialization();
    graph.serializeSingleShape(&serializer);
    serializer.finishSerialization();
    bParse::btBulletFile file(
        reinterpret_cast<char*>(const_cast<unsigned char*>(serializer.getBufferPointer())),
        serializer.getCurrentBufferSize());
    btBulletWorldImporter importer;
    importer.setVerboseMode(0);
    ASSERT_TRUE(importer.loadFileFromMemory(&file));
    ASSERT_EQ(importer.getNumCollisionShapes(), 1);
    const btCollisionShape* shape = importer.getCollisionShapeByIndex(0);
    ASSERT_EQ(shape->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
    EXPECT_EQ(static_cast<const btConvexHullShape*>(shape)->getNumPoints(), graph.getNumPoints());
    importer.deleteAllData();  // the importer owns what it made but does not free it
}
