// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/SweepFile.h>

#include "JsonSchema.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

using namespace btfracture;

namespace {

const std::string kSweep = std::string(BTFRACTURE_TEST_DATA_DIR) + "/sweeps/box_sweep.json";
const std::string kScene = std::string(BTFRACTURE_TEST_DATA_DIR) + "/scenes/sweep_box.json";

// The error reading a sweep file with this text (in the test data's sweeps folder).
std::string errorOf(const std::string& json) {
    const std::string path = std::string(BTFRACTURE_TEST_DATA_DIR) + "/sweeps/test_sweep_file.tmp.json";
    std::ofstream(path) << json;
    std::string error = "(no error)";
    try {
        SweepRunBuilder(readSweepFile(path)).parameters(0);
    } catch (const Error& e) {
        error = e.what();
    }
    std::filesystem::remove(path);
    return error;
}

std::string sweepWith(const std::string& extra) {
    return R"({"scene": "../scenes/sweep_box.json", "target": "slab", "impactor": "ball", "runs": 4, "seed": 1)" +
           extra + "}";
}

}  // namespace

TEST(SweepFile, ShardsCoverEveryRunOnce) {
    for (int runs = 0; runs <= 20; ++runs)
        for (int shards = 1; shards <= 7; ++shards) {
            int next = 0;
            for (int k = 0; k < shards; ++k) {
                const auto [first, last] = shardRuns(runs, k, shards);
                EXPECT_EQ(first, next) << runs << " runs, shard " << k << "/" << shards;
                EXPECT_LE(last - first, runs / shards + 1);
                EXPECT_GE(last - first, runs / shards);
                next = last;
            }
            EXPECT_EQ(next, runs);
        }
    EXPECT_THROW(shardRuns(8, 2, 2), Error);
    EXPECT_THROW(shardRuns(8, -1, 2), Error);
    EXPECT_THROW(shardRuns(8, 0, 0), Error);
}

// Run i depends on (sweep file, i) only: another builder, another order, the same numbers.
TEST(SweepFile, RunsArePureFunctionsOfTheirIndex) {
    const SweepSpec spec = readSweepFile(kSweep);
    const SweepRunBuilder a(spec), b(spec);
    std::set<double> speeds;
    for (int i = spec.runs - 1; i >= 0; --i) {
        const SweepRunParameters p = a.parameters(i), q = b.parameters(i), again = a.parameters(i);
        EXPECT_EQ(p.speed, q.speed);
        EXPECT_EQ(p.pointRest, q.pointRest);
        EXPECT_EQ(p.direction, q.direction);
        EXPECT_EQ(p.seed, q.seed);
        EXPECT_EQ(p.targetOrientation.coeffs(), q.targetOrientation.coeffs());
        EXPECT_EQ(p.impactorScale, again.impactorScale);
        EXPECT_EQ(p.impactorMass, again.impactorMass);
        EXPECT_EQ(p.method, again.method);
        speeds.insert(p.speed);
    }
    EXPECT_EQ(speeds.size(), static_cast<size_t>(spec.runs));  // runs differ
    // Another sweep seed, other runs.
    SweepSpec other = spec;
    other.seed = spec.seed + 1;
    EXPECT_NE(SweepRunBuilder(other).parameters(0).speed, a.parameters(0).speed);
}

// Every drawn value lies in its distribution; the impactor starts clear of the impact point,
// aimed at it.
TEST(SweepFile, ParametersFollowTheDistributions) {
    const SweepSpec spec = readSweepFile(kSweep);
    const SweepRunBuilder builder(spec);
    const double halfAngle = 25.0 * M_PI / 180.0;
    for (int i = 0; i < 64; ++i) {
        const SweepRunParameters p = builder.parameters(i);
        EXPECT_GE(p.speed, 3.0);
        EXPECT_LT(p.speed, 9.0);
        EXPECT_GE(p.impactorScale, 0.8);
        EXPECT_LT(p.impactorScale, 1.25);
        ASSERT_TRUE(p.impactorMass);
        EXPECT_TRUE(*p.impactorMass == 0.2 || *p.impactorMass == 0.5);
        EXPECT_TRUE(p.method == FractureMethod::Estimated || p.method == FractureMethod::Hybrid);
        // On the slab's surface (half extents 0.1, 0.02, 0.06, held in Bullet's float), on a face
        // looking up.
        const Eigen::Vector3d& x = p.pointRest;
        EXPECT_LE(std::abs(x.x()), 0.1 + 1e-7);
        EXPECT_LE(std::abs(x.y()), 0.02 + 1e-7);
        EXPECT_LE(std::abs(x.z()), 0.06 + 1e-7);
        EXPECT_NEAR(std::max({std::abs(x.x()) / 0.1, std::abs(x.y()) / 0.02, std::abs(x.z()) / 0.06}), 1.0,
                    1e-6);
        const Eigen::Vector3d normalWorld = p.targetOrientation * p.normalRest;
        EXPECT_GE(normalWorld.y(), 0.5);
        // Yaw only: the up axis stays up.
        EXPECT_NEAR((p.targetOrientation * Eigen::Vector3d::UnitY()).y(), 1.0, 1e-12);
        EXPECT_NEAR(p.direction.norm(), 1.0, 1e-12);
        EXPECT_GE(p.direction.dot(-normalWorld), std::cos(halfAngle) - 1e-12);
        EXPECT_TRUE(p.pointWorld.isApprox(builder.targetRestToWorld(p) * p.pointRest, 1e-12));

        const Scene scene = builder.scene(p);
        const SceneBody& ball = scene.bodies[2];
        const double radius = 0.02 * p.impactorScale;
        EXPECT_NEAR(ball.shape.radius * ball.scale.x(), radius, 1e-12);
        EXPECT_TRUE((ball.position + (radius + spec.standoff) * p.direction).isApprox(p.pointWorld, 1e-12));
        EXPECT_TRUE(ball.linearVelocity.isApprox(p.speed * p.direction, 1e-12));
        EXPECT_EQ(*ball.mass, *p.impactorMass);
        EXPECT_EQ(scene.bodies[1].fracture.method, p.method);
        EXPECT_EQ(scene.effects.seed, p.seed);
    }
}

TEST(SweepFile, BadInputNamesTheProblem) {
    const auto has = [](const std::string& text, const std::string& part) {
        return text.find(part) != std::string::npos;
    };
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "speeed": 3)")), "speeed: unknown key"));
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "vary": {"speed": {"normal": [1, 2]}})")),
                    "vary.speed.normal: unknown distribution"));
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "vary": {"speed": {"uniform": [5, 2]}})")), "low <= high"));
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "vary": {"speed": -1})")), "vary.speed: expected a number > 0"));
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "vary": {"method": "fast"})")), "vary.method"));
    EXPECT_TRUE(has(errorOf(sweepWith(R"(, "vary": {"target_orientation": "random"})")),
                    "expected \"fixed\", \"about_up\" or \"uniform\""));
    EXPECT_TRUE(has(errorOf(R"({"scene": "../scenes/sweep_box.json", "target": "cube", "impactor": "ball",
        "runs": 4, "seed": 1})"),
                    "target: no body named 'cube'"));
    EXPECT_TRUE(has(errorOf(R"({"scene": "../scenes/sweep_box.json", "target": "slab", "impactor": "ground",
        "runs": 4, "seed": 1})"),
                    "impactor 'ground': expected a sphere or box body, got a plane"));
    EXPECT_TRUE(has(errorOf(R"({"scene": "../scenes/sweep_box.json", "target": "slab", "impactor": "ball",
        "runs": 0, "seed": 1})"),
                    "runs: expected an integer >= 1"));
    EXPECT_TRUE(has(errorOf(R"({"scene": "../scenes/nope.json", "target": "slab", "impactor": "ball",
        "runs": 4, "seed": 1})"),
                    "nope.json"));
    EXPECT_TRUE(
        has(errorOf(sweepWith(R"(, "vary": {"impact_facing": {"direction": [1, 1, 0], "min_cos": 0.9}})")),
            "vary.impact_facing: run 0: no point of 'slab' faces that way"));
}

// The shipped sweeps follow demos/sweep/sweep.schema.json, and what the schema rejects for a key
// the reader rejects too.
TEST(SweepFile, ExamplesFollowTheSchema) {
    using Json = nlohmann::json;
    const std::string demos = std::string(BTFRACTURE_MESH_DIR) + "/../sweep";
    const test::JsonSchema schema(Json::parse(readWholeFile(demos + "/sweep.schema.json", "schema")));
    for (const std::string& file : {demos + "/bunny_impacts.json", kSweep}) {
        const std::vector<std::string> problems = schema.validate(Json::parse(readWholeFile(file, "sweep")));
        EXPECT_TRUE(problems.empty()) << file << ": " << (problems.empty() ? "" : problems[0]);
        EXPECT_NO_THROW(SweepRunBuilder(readSweepFile(file)).parameters(0)) << file;
    }
    Json bad = Json::parse(readWholeFile(kSweep, "sweep"));
    bad["vary"]["speeds"] = 3;
    EXPECT_FALSE(schema.validate(bad).empty());
    bad["vary"].erase("speeds");
    bad["vary"]["target_orientation"] = "tumbling";
    EXPECT_FALSE(schema.validate(bad).empty());
}
