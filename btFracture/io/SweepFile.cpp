// SPDX-License-Identifier: Zlib
#include <btFracture/io/SweepFile.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/io/FractureSceneWorldFactory.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/SceneWorld.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace btfracture {
namespace {

using Json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

// Streams of the counter-based generator, one per quantity: adding a quantity never shifts
// another's values.
enum Stream : std::uint64_t { kSpeed = 1, kPoint, kDirection, kScale, kMass, kOrientation, kSeed, kMethod };

// Uniform numbers for one (sweep seed, run, quantity): the n-th is a hash of the four
// (splitmix64 mixing, FractureSceneWorldFactory.h's combineSeeds), so no state is shared.
class RunRandom {
public:
    RunRandom(std::uint64_t seed, int run, Stream stream)
        : key_(combineSeeds(combineSeeds(seed, static_cast<std::uint64_t>(run)), stream)) {}
    std::uint64_t bits() { return combineSeeds(key_, counter_++); }
    double uniform() { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }  // [0, 1)

private:
    std::uint64_t key_, counter_ = 0;
};

double draw(const SweepNumber& number, RunRandom& random) {
    switch (number.kind) {
        case SweepNumber::Kind::Constant:
            return number.values[0];
        case SweepNumber::Kind::Uniform:
            return number.values[0] + (number.values[1] - number.values[0]) * random.uniform();
        case SweepNumber::Kind::Choice:
            return number.values[std::min(number.values.size() - 1,
                                          static_cast<size_t>(random.uniform() * number.values.size()))];
    }
    return 0.0;
}

// A unit vector at angle <= maxAngle [rad] from `axis`, uniform over that cap of the sphere.
Eigen::Vector3d inCone(const Eigen::Vector3d& axis, double maxAngle, RunRandom& random) {
    const double cosTheta = 1.0 - random.uniform() * (1.0 - pmath::cos(maxAngle));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * random.uniform();
    const Eigen::Vector3d helper =
        std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = axis.cross(helper).normalized(), v = axis.cross(u);
    return (cosTheta * axis + sinTheta * (pmath::cos(phi) * u + pmath::sin(phi) * v)).normalized();
}

class SweepParser {
public:
    explicit SweepParser(std::string source) : source_(std::move(source)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw Error(source_ + ": " + path + ": " + what);
    }

    void keys(const Json& object, const std::string& path, const std::set<std::string>& allowed) const {
        if (!object.is_object()) fail(path, "expected an object");
        for (const auto& item : object.items())
            if (!allowed.count(item.key()))
                fail(path.empty() ? item.key() : path + "." + item.key(), "unknown key");
    }

    double number(const Json& value, const std::string& path) const {
        if (!value.is_number()) fail(path, "expected a number, got " + value.dump());
        return value.get<double>();
    }

    int integer(const Json& value, const std::string& path, int minimum) const {
        if (!value.is_number_integer() || value.get<long long>() < minimum ||
            value.get<long long>() > 1000000000)
            fail(path, "expected an integer >= " + std::to_string(minimum) + ", got " + value.dump());
        return value.get<int>();
    }

    // number | {"uniform": [low, high]} | {"choice": [a, b, ...]}, every value in [minimum, inf).
    SweepNumber distribution(const Json& value, const std::string& path, double minimum,
                             bool strictlyAbove) const {
        const auto check = [&](double x, const std::string& where) {
            if (!std::isfinite(x) || x < minimum || (strictlyAbove && x == minimum))
                fail(where, std::string("expected a number ") + (strictlyAbove ? "> " : ">= ") +
                                format(minimum) + ", got " + format(x));
            return x;
        };
        SweepNumber n;
        if (value.is_number()) {
            n.values = {check(number(value, path), path)};
            return n;
        }
        if (!value.is_object() || value.size() != 1)
            fail(path, "expected a number, {\"uniform\": [low, high]} or {\"choice\": [...]}");
        // The object's one entry (not through items(): its iterator is a temporary that a binding
        // would outlive).
        const std::string kind = value.begin().key();
        const Json& list = value.begin().value();
        const std::string where = path + "." + kind;
        if (kind != "uniform" && kind != "choice")
            fail(where, "unknown distribution (expected \"uniform\" or \"choice\")");
        if (!list.is_array() || list.empty()) fail(where, "expected a non-empty array of numbers");
        for (size_t i = 0; i < list.size(); ++i)
            n.values.push_back(check(number(list[i], where + "[" + std::to_string(i) + "]"),
                                     where + "[" + std::to_string(i) + "]"));
        if (kind == "uniform") {
            if (n.values.size() != 2 || n.values[0] > n.values[1])
                fail(where, "expected [low, high] with low <= high");
            n.kind = SweepNumber::Kind::Uniform;
        } else {
            n.kind = SweepNumber::Kind::Choice;
        }
        return n;
    }

    static std::string format(double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", x);
        return text;
    }

    SweepSpec parse(const Json& root, const std::string& baseDirectory) const {
        keys(root, "",
             {"$schema", "description", "scene", "target", "impactor", "runs", "seed", "steps",
              "bem_triangles", "vary"});
        SweepSpec s;
        s.file = source_;
        for (const char* key : {"scene", "target", "impactor", "runs", "seed"})
            if (!root.contains(key)) fail(key, "missing");
        for (const char* key : {"scene", "target", "impactor"})
            if (!root[key].is_string() || root[key].get<std::string>().empty())
                fail(key, "expected a non-empty string, got " + root[key].dump());
        const std::filesystem::path scene(root["scene"].get<std::string>());
        s.sceneFile = (scene.is_absolute() ? scene : std::filesystem::path(baseDirectory) / scene)
                          .lexically_normal()
                          .string();
        s.target = root["target"].get<std::string>();
        s.impactor = root["impactor"].get<std::string>();
        if (s.target == s.impactor) fail("impactor", "must differ from the target");
        s.runs = integer(root["runs"], "runs", 1);
        if (!root["seed"].is_number_unsigned())
            fail("seed", "expected an integer >= 0, got " + root["seed"].dump());
        s.seed = root["seed"].get<std::uint64_t>();
        if (root.contains("steps")) s.steps = integer(root["steps"], "steps", 1);
        if (root.contains("bem_triangles"))
            s.bemTriangles = integer(root["bem_triangles"], "bem_triangles", 4);

        const Json vary = root.value("vary", Json::object());
        keys(vary, "vary",
             {"speed", "direction_half_angle_deg", "impact_facing", "standoff", "impactor_scale",
              "impactor_mass", "target_orientation", "material_noise_seed", "method"});
        s.speed = vary.contains("speed") ? distribution(vary["speed"], "vary.speed", 0.0, true)
                                         : SweepNumber{{}, {5.0}};
        s.coneHalfAngleDegrees =
            vary.contains("direction_half_angle_deg")
                ? distribution(vary["direction_half_angle_deg"], "vary.direction_half_angle_deg", 0.0, false)
                : SweepNumber{{}, {0.0}};
        for (double angle : s.coneHalfAngleDegrees.values)
            if (angle >= 90.0) fail("vary.direction_half_angle_deg", "expected angles below 90 degrees");
        if (vary.contains("impact_facing")) {
            const Json& f = vary["impact_facing"];
            keys(f, "vary.impact_facing", {"direction", "min_cos"});
            if (!f.contains("direction") || !f["direction"].is_array() || f["direction"].size() != 3)
                fail("vary.impact_facing.direction", "expected [x, y, z]");
            for (int i = 0; i < 3; ++i)
                s.facing[i] = number(f["direction"][i], "vary.impact_facing.direction");
            if (!(s.facing.norm() > 0.0)) fail("vary.impact_facing.direction", "expected a non-zero vector");
            s.facing.normalize();
            s.minFacingCosine =
                f.contains("min_cos") ? number(f["min_cos"], "vary.impact_facing.min_cos") : 0.0;
            if (s.minFacingCosine < -1.0 || s.minFacingCosine >= 1.0)
                fail("vary.impact_facing.min_cos", "expected a number in [-1, 1)");
        }
        if (vary.contains("standoff")) {
            s.standoff = number(vary["standoff"], "vary.standoff");
            if (!(s.standoff > 0.0)) fail("vary.standoff", "expected a number > 0 [m]");
        }
        s.impactorScale = vary.contains("impactor_scale")
                              ? distribution(vary["impactor_scale"], "vary.impactor_scale", 0.0, true)
                              : SweepNumber{{}, {1.0}};
        if (vary.contains("impactor_mass"))
            s.impactorMass = distribution(vary["impactor_mass"], "vary.impactor_mass", 0.0, true);
        if (vary.contains("target_orientation")) {
            const Json& o = vary["target_orientation"];
            const std::string word = o.is_string() ? o.get<std::string>() : std::string();
            s.orientation = word == "fixed"      ? SweepOrientation::Fixed
                            : word == "about_up" ? SweepOrientation::AboutUp
                            : word == "uniform"
                                ? SweepOrientation::Uniform
                                : (fail("vary.target_orientation",
                                        "expected \"fixed\", \"about_up\" or \"uniform\", got " + o.dump()),
                                   SweepOrientation::Fixed);
        }
        if (vary.contains("material_noise_seed")) {
            const Json& n = vary["material_noise_seed"];
            if (n != "per_run" && n != "scene")
                fail("vary.material_noise_seed", "expected \"per_run\" or \"scene\", got " + n.dump());
            s.noiseSeedPerRun = n == "per_run";
        }
        if (vary.contains("method")) {
            const Json& m = vary["method"];
            const std::string path = "vary.method";
            if (m.is_string()) {
                s.methods = {parseFractureMethod(m.get<std::string>(), path)};
            } else if (m.is_object() && m.size() == 1 && m.contains("choice") && m["choice"].is_array() &&
                       !m["choice"].empty()) {
                for (const Json& word : m["choice"]) {
                    if (!word.is_string())
                        fail(path + ".choice", "expected method names, got " + word.dump());
                    s.methods.push_back(parseFractureMethod(word.get<std::string>(), path + ".choice"));
                }
            } else {
                fail(path, "expected a method name or {\"choice\": [names]}");
            }
        }
        return s;
    }

private:
    std::string source_;
};

// Area-weighted pick of a triangle, then a uniform point in it.
struct SurfacePoint {
    Eigen::Vector3d point, normal;
};

SurfacePoint surfacePoint(const TriangleMesh& mesh, const std::vector<double>& cumulative,
                          RunRandom& random) {
    const double target = random.uniform() * cumulative.back();
    const size_t t =
        std::min(cumulative.size() - 1,
                 static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), target) -
                                     cumulative.begin()));
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    double u = random.uniform(), v = random.uniform();
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    return {a + u * (b - a) + v * (c - a), (b - a).cross(c - a).normalized()};
}

// Radius of the impactor's bounding sphere at scale 1 (scene scale included) [m].
double impactorRadius(const SceneBody& body, const std::string& source) {
    if (body.shape.type == SceneShapeType::Sphere) return body.shape.radius * body.scale.x();
    if (body.shape.type == SceneShapeType::Box) return body.shape.halfExtents.cwiseProduct(body.scale).norm();
    throw Error(source + ": impactor '" + body.name + "': expected a sphere or box body, got a " +
                toString(body.shape.type));
}

}  // namespace

SweepSpec readSweepFile(const std::string& path) {
    const std::string text = readWholeFile(path, "sweep file");
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::exception& e) {
        throw Error(path + ": not valid JSON: " + e.what());
    }
    return SweepParser(path).parse(root, std::filesystem::path(path).parent_path().string());
}

std::pair<int, int> shardRuns(int runs, int k, int shards) {
    if (shards < 1 || k < 0 || k >= shards)
        throw Error("shard " + std::to_string(k) + "/" + std::to_string(shards) +
                    ": expected k/K with 0 <= k < K");
    const auto bound = [&](int i) { return static_cast<int>(static_cast<long long>(runs) * i / shards); };
    return {bound(k), bound(k + 1)};
}

SweepRunBuilder::SweepRunBuilder(const SweepSpec& spec) : spec_(spec), base_(readSceneFile(spec.sceneFile)) {
    const auto find = [&](const std::string& name, const char* role) {
        for (size_t i = 0; i < base_.bodies.size(); ++i)
            if (base_.bodies[i].name == name) return i;
        throw Error(spec_.file + ": " + role + ": no body named '" + name + "' in " + spec_.sceneFile);
    };
    targetIndex_ = find(spec_.target, "target");
    impactorIndex_ = find(spec_.impactor, "impactor");
    const SceneBody& target = base_.bodies[targetIndex_];
    if (target.shape.type == SceneShapeType::Plane || target.isStatic() ||
        target.motion == SceneMotion::Kinematic)
        throw Error(spec_.file + ": target: '" + target.name +
                    "' must be a dynamic (or sleeping) mesh, box or sphere");
    if (!target.fracture.fracturable)
        throw Error(spec_.file + ": target: '" + target.name + "' is not breakable in " + spec_.sceneFile +
                    " (effects.fracture)");
    impactorRadius(base_.bodies[impactorIndex_], spec_.file);
    if (spec_.bemTriangles) {
        SceneBody& t = base_.bodies[targetIndex_];
        t.fracture.bemTriangleTarget = *spec_.bemTriangles;
        t.fracture.collisionTriangleTarget =
            std::max(t.fracture.collisionTriangleTarget, *spec_.bemTriangles);
    }
    if (spec_.steps) base_.world.steps = *spec_.steps;

    // The target's surface as SceneWorld builds it (scaled, body frame), brought to the rest frame.
    Scene alone = base_;
    alone.bodies = {target};
    alone.bodies[0].fracture = unbreakable();
    const SceneWorld world(alone);
    const SceneWorld::Body& body = world.bodies()[0];
    const btTransform& t = body.rigidBody->getWorldTransform();
    Eigen::Isometry3d bodyToWorld = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) bodyToWorld.linear()(r, c) = t.getBasis()[r][c];
        bodyToWorld.translation()[r] = t.getOrigin()[r];
    }
    Eigen::Isometry3d restToWorld = Eigen::Isometry3d::Identity();
    restToWorld.linear() = target.orientation.toRotationMatrix();
    restToWorld.translation() = target.position;
    const Eigen::Isometry3d bodyToRest = restToWorld.inverse() * bodyToWorld;
    restSurface_ = body.surface;
    for (Eigen::Vector3d& v : restSurface_.vertices) v = bodyToRest * v;
    double area = 0.0;
    for (const auto& tri : restSurface_.triangles) {
        const auto& p = restSurface_.vertices;
        area += 0.5 * (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).norm();
        cumulativeArea_.push_back(area);
    }
    if (cumulativeArea_.empty() || !(area > 0.0))
        throw Error(spec_.file + ": target '" + target.name + "' has no surface area");
}

Eigen::Isometry3d SweepRunBuilder::targetRestToWorld(const SweepRunParameters& run) const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = run.targetOrientation.toRotationMatrix();
    pose.translation() = base_.bodies[targetIndex_].position;
    return pose;
}

SweepRunParameters SweepRunBuilder::parameters(int index) const {
    SweepRunParameters run;
    run.index = index;
    const SceneBody& target = base_.bodies[targetIndex_];

    RunRandom orientation(spec_.seed, index, kOrientation);
    Eigen::Quaterniond turn = Eigen::Quaterniond::Identity();
    if (spec_.orientation == SweepOrientation::Uniform) {  // Shoemake's uniform rotation
        const double u1 = orientation.uniform(), u2 = orientation.uniform(), u3 = orientation.uniform();
        const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
        turn = Eigen::Quaterniond(b * pmath::cos(2 * kPi * u3), a * pmath::sin(2 * kPi * u2),
                                  a * pmath::cos(2 * kPi * u2), b * pmath::sin(2 * kPi * u3));
    } else if (spec_.orientation == SweepOrientation::AboutUp) {
        const Eigen::Vector3d up = base_.world.gravity.norm() > 0.0
                                       ? Eigen::Vector3d(-base_.world.gravity.normalized())
                                       : Eigen::Vector3d::UnitY();
        const double half = kPi * orientation.uniform();  // half of an angle in [0, 2 pi)
        turn = Eigen::Quaterniond(pmath::cos(half), pmath::sin(half) * up.x(), pmath::sin(half) * up.y(),
                                  pmath::sin(half) * up.z());
    }
    run.targetOrientation = (turn * target.orientation).normalized();
    const Eigen::Isometry3d restToWorld = targetRestToWorld(run);

    // Rejection sampling of the facing condition, on the point stream only.
    RunRandom pointRandom(spec_.seed, index, kPoint);
    constexpr int kAttempts = 10000;
    int attempt = 0;
    for (; attempt < kAttempts; ++attempt) {
        const SurfacePoint p = surfacePoint(restSurface_, cumulativeArea_, pointRandom);
        run.pointRest = p.point;
        run.normalRest = p.normal;
        if (spec_.facing.isZero() ||
            (restToWorld.linear() * p.normal).dot(spec_.facing) >= spec_.minFacingCosine)
            break;
    }
    if (attempt == kAttempts)
        throw Error(spec_.file + ": vary.impact_facing: run " + std::to_string(index) + ": no point of '" +
                    target.name + "' faces that way in " + std::to_string(kAttempts) + " tries");
    run.pointWorld = restToWorld * run.pointRest;
    const Eigen::Vector3d inward = -(restToWorld.linear() * run.normalRest);

    RunRandom direction(spec_.seed, index, kDirection);
    const double halfAngle = draw(spec_.coneHalfAngleDegrees, direction) * kPi / 180.0;
    run.direction = inCone(inward, halfAngle, direction);
    RunRandom speed(spec_.seed, index, kSpeed);
    run.speed = draw(spec_.speed, speed);
    RunRandom scale(spec_.seed, index, kScale);
    run.impactorScale = draw(spec_.impactorScale, scale);
    if (spec_.impactorMass) {
        RunRandom mass(spec_.seed, index, kMass);
        run.impactorMass = draw(*spec_.impactorMass, mass);
    }
    run.seed = base_.effects.seed;
    if (spec_.noiseSeedPerRun) run.seed = RunRandom(spec_.seed, index, kSeed).bits() >> 1;  // JSON-safe
    run.method = target.fracture.method;
    if (!spec_.methods.empty()) {
        RunRandom method(spec_.seed, index, kMethod);
        run.method = spec_.methods[std::min(spec_.methods.size() - 1,
                                            static_cast<size_t>(method.uniform() * spec_.methods.size()))];
    }
    return run;
}

Scene SweepRunBuilder::scene(const SweepRunParameters& run) const {
    Scene scene = base_;
    SceneBody& target = scene.bodies[targetIndex_];
    SceneBody& impactor = scene.bodies[impactorIndex_];
    target.orientation = run.targetOrientation;
    target.fracture.method = run.method;
    impactor.scale *= run.impactorScale;
    if (run.impactorMass) impactor.mass = *run.impactorMass;
    const double radius = impactorRadius(impactor, spec_.file);
    impactor.position = run.pointWorld - run.direction * (radius + spec_.standoff);
    impactor.linearVelocity = run.speed * run.direction;
    impactor.angularVelocity.setZero();
    if (impactor.motion == SceneMotion::Sleeping) impactor.motion = SceneMotion::Dynamic;
    scene.effects.seed = run.seed;
    scene.effects.outputs = SceneOutputFormats{};
    scene.effects.outputs.obj = false;
    scene.effects.outputs.csv = true;
    return scene;
}

}  // namespace btfracture
