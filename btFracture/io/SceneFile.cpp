// SPDX-License-Identifier: Zlib
#include <btFracture/io/SceneFile.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/io/ReadFile.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

namespace btfracture {

const char* toString(SceneShapeType type) {
    switch (type) {
        case SceneShapeType::Mesh:
            return "mesh";
        case SceneShapeType::Box:
            return "box";
        case SceneShapeType::Sphere:
            return "sphere";
        case SceneShapeType::Plane:
            return "plane";
    }
    return "?";
}

const char* toString(SceneMeshCollision collision) {
    return collision == SceneMeshCollision::GImpact ? "gimpact" : "convex_hull";
}

FractureMethod parseFractureMethod(const std::string& word, const std::string& what) {
    try {
        return fractureMethodFromString(word);
    } catch (const Error& e) {
        throw Error(what + ": " + e.what());
    }
}

const char* toString(SceneMotion motion) {
    switch (motion) {
        case SceneMotion::Dynamic:
            return "dynamic";
        case SceneMotion::Sleeping:
            return "sleeping";
        case SceneMotion::Kinematic:
            return "kinematic";
    }
    return "?";
}

void overrideFractureMethod(Scene& scene, FractureMethod method) {
    for (SceneBody& body : scene.bodies)
        if (body.fracture.fracturable) body.fracture.method = method;
}

namespace {

using Json = nlohmann::json;

std::string child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}
std::string element(const std::string& path, size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

// Short rendering of a JSON value for messages.
std::string shown(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

class SceneParser {
public:
    SceneParser(std::string source, std::string baseDirectory)
        : source_(std::move(source)), baseDirectory_(std::move(baseDirectory)) {}

    Scene parse(const Json& root) {
        Scene scene;
        requireObject(root, "", "the scene (a JSON object)");
        allowOnly(root, "", {"$schema", "description", "world", "bodies", "outputs", "effects"});
        if (root.contains("$schema")) text(root["$schema"], "$schema");  // for editors (scene.schema.json)
        if (root.contains("description")) text(root["description"], "description");
        if (root.contains("world")) scene.world = world(root["world"], "world");
        if (!root.contains("bodies")) fail("bodies", "missing; expected an array of bodies");
        const Json& bodies = root["bodies"];
        if (!bodies.is_array() || bodies.empty())
            fail("bodies", "expected a non-empty array of bodies, got " + shown(bodies));
        std::set<std::string> names;
        for (size_t i = 0; i < bodies.size(); ++i) {
            const std::string path = element("bodies", i);
            SceneBody b = body(bodies[i], path, i);
            if (!names.insert(b.name).second)
                fail(child(path, "name"), "body name '" + b.name + "' is used twice");
            scene.bodies.push_back(std::move(b));
        }
        if (root.contains("outputs")) scene.outputs = outputs(root["outputs"], "outputs");
        if (root.contains("effects")) effects(root["effects"], "effects", scene);
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw Error(source_ + ": " + (path.empty() ? std::string() : path + ": ") + problem);
    }

    void requireObject(const Json& value, const std::string& path, const std::string& what) const {
        if (!value.is_object()) fail(path, "expected " + what + ", got " + shown(value));
    }

    void allowOnly(const Json& object, const std::string& path,
                   std::initializer_list<const char*> keys) const {
        for (const auto& item : object.items()) {
            if (std::any_of(keys.begin(), keys.end(), [&](const char* k) { return item.key() == k; }))
                continue;
            std::string known;
            for (const char* k : keys) known += std::string(known.empty() ? "" : ", ") + k;
            fail(child(path, item.key()), "unknown key (expected one of: " + known + ")");
        }
    }

    double number(const Json& value, const std::string& path, const std::string& expected) const {
        if (!value.is_number() || !std::isfinite(value.get<double>()))
            fail(path, "expected " + expected + ", got " + shown(value));
        return value.get<double>();
    }

    // A finite number >= 0; `expected` says what (e.g. "a mass >= 0 [kg]").
    double nonNegative(const Json& value, const std::string& path, const std::string& expected) const {
        const double x = number(value, path, expected);
        if (!(x >= 0.0)) fail(path, "expected " + expected + ", got " + shown(value));
        return x;
    }

    double positive(const Json& value, const std::string& path, const std::string& unit) const {
        const std::string expected = "a positive number" + (unit.empty() ? "" : " [" + unit + "]");
        const double x = number(value, path, expected);
        if (!(x > 0.0)) fail(path, "expected " + expected + ", got " + shown(value));
        return x;
    }

    int integer(const Json& value, const std::string& path, int minimum, int maximum = 1000000000) const {
        const std::string expected = maximum < 1000000000 ? "an integer in [" + std::to_string(minimum) +
                                                                ", " + std::to_string(maximum) + "]"
                                                          : "an integer >= " + std::to_string(minimum);
        if (!value.is_number_integer() || value.get<long long>() < minimum ||
            value.get<long long>() > maximum)
            fail(path, "expected " + expected + ", got " + shown(value));
        return static_cast<int>(value.get<long long>());
    }

    std::uint64_t seed(const Json& value, const std::string& path) const {
        if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<long long>() >= 0))
            fail(path, "expected an integer seed >= 0, got " + shown(value));
        return value.get<std::uint64_t>();
    }

    // One of `words` (the enum's spellings), as its index.
    size_t choice(const Json& value, const std::string& path,
                  std::initializer_list<const char*> words) const {
        std::string expected;
        size_t k = 0;
        for (const char* w : words)
            expected += std::string(k++ == 0 ? "" : k == words.size() ? " or " : ", ") + "\"" + w + "\"";
        if (value.is_string()) {
            k = 0;
            for (const char* w : words) {
                if (value.get<std::string>() == w) return k;
                ++k;
            }
        }
        fail(path, "expected " + expected + ", got " + shown(value));
    }

    Eigen::Vector3d vector3(const Json& value, const std::string& path, const std::string& unit) const {
        const std::string expected = "an array of 3 numbers" + (unit.empty() ? "" : " [" + unit + "]");
        if (!value.is_array() || value.size() != 3)
            fail(path, "expected " + expected + ", got " + shown(value));
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) v[k] = number(value[k], element(path, k), "a number");
        return v;
    }

    std::string text(const Json& value, const std::string& path) const {
        if (!value.is_string()) fail(path, "expected a string, got " + shown(value));
        return value.get<std::string>();
    }

    bool boolean(const Json& value, const std::string& path) const {
        if (!value.is_boolean()) fail(path, "expected true or false, got " + shown(value));
        return value.get<bool>();
    }

    SceneWorldSettings world(const Json& value, const std::string& path) const {
        requireObject(value, path, "an object");
        allowOnly(value, path, {"gravity", "dt", "steps", "substeps"});
        SceneWorldSettings w;
        if (value.contains("gravity")) w.gravity = vector3(value["gravity"], child(path, "gravity"), "m/s^2");
        if (value.contains("dt")) w.dt = positive(value["dt"], child(path, "dt"), "s");
        if (value.contains("steps")) w.steps = integer(value["steps"], child(path, "steps"), 0);
        if (value.contains("substeps")) w.substeps = integer(value["substeps"], child(path, "substeps"), 1);
        return w;
    }

    SceneOutputs outputs(const Json& value, const std::string& path) const {
        requireObject(value, path, "an object");
        allowOnly(value, path,
                  {"directory", "motion_every_n_steps", "obj_every_n_steps", "png_every_n_steps", "image"});
        SceneOutputs o;
        if (value.contains("directory")) {
            o.directory = text(value["directory"], child(path, "directory"));
            if (o.directory.empty()) fail(child(path, "directory"), "expected a non-empty folder path");
        }
        if (value.contains("motion_every_n_steps"))
            o.motionEveryNSteps =
                integer(value["motion_every_n_steps"], child(path, "motion_every_n_steps"), 1);
        if (value.contains("obj_every_n_steps"))
            o.objEveryNSteps = integer(value["obj_every_n_steps"], child(path, "obj_every_n_steps"), 0);
        if (value.contains("png_every_n_steps"))
            o.pngEveryNSteps = integer(value["png_every_n_steps"], child(path, "png_every_n_steps"), 0);
        if (value.contains("image")) o.image = image(value["image"], child(path, "image"));
        return o;
    }

    RenderSettings image(const Json& value, const std::string& path) const {
        requireObject(value, path, "an object");
        allowOnly(value, path, {"width", "height", "projection", "shading", "view", "supersampling"});
        RenderSettings m;
        if (value.contains("width")) m.width = integer(value["width"], child(path, "width"), 16, 8192);
        if (value.contains("height")) m.height = integer(value["height"], child(path, "height"), 16, 8192);
        if (value.contains("projection"))
            m.projection = static_cast<Projection>(
                choice(value["projection"], child(path, "projection"), {"perspective", "orthographic"}));
        if (value.contains("shading"))
            m.shading =
                static_cast<Shading>(choice(value["shading"], child(path, "shading"), {"gouraud", "flat"}));
        if (value.contains("supersampling"))
            m.supersampling = integer(value["supersampling"], child(path, "supersampling"), 1, 4);
        if (value.contains("view")) {
            m.view = vector3(value["view"], child(path, "view"), "");
            if (!(m.view.norm() > 1e-12))
                fail(child(path, "view"), "expected a non-zero direction, got " + shown(value["view"]));
        }
        return m;
    }

    // effects: output formats, the run seed and the per-body fracture settings (after the bodies).
    void effects(const Json& value, const std::string& path, Scene& scene) const {
        requireObject(value, path, "an object");
        allowOnly(value, path,
                  {"outputs", "seed", "crack_cut", "idle_matrix_budget_mb", "surface_seeds",
                   "estimator_surface_fronts", "fragment_sleeping", "fracture"});
        if (value.contains("outputs")) {
            const Json& list = value["outputs"];
            const std::string lpath = child(path, "outputs");
            if (!list.is_array())
                fail(lpath,
                     "expected an array of \"motion\", \"gltf\", \"obj\", \"vdb\", \"csv\", \"png\", got " +
                         shown(list));
            SceneOutputFormats f;
            f.motion = false;
            f.gltf = false;
            std::set<size_t> seen;
            for (size_t i = 0; i < list.size(); ++i) {
                const size_t k =
                    choice(list[i], element(lpath, i), {"motion", "gltf", "obj", "vdb", "csv", "png"});
                if (!seen.insert(k).second) fail(element(lpath, i), "listed twice: " + shown(list[i]));
                bool* flags[] = {&f.motion, &f.gltf, &f.obj, &f.vdb, &f.csv, &f.png};
                *flags[k] = true;
            }
            scene.effects.outputs = f;
        }
        if (value.contains("seed")) scene.effects.seed = seed(value["seed"], child(path, "seed"));
        if (value.contains("crack_cut"))
            scene.effects.voxelFronts =
                choice(value["crack_cut"], child(path, "crack_cut"), {"markers", "coarse_sheet"}) == 0;
        if (value.contains("idle_matrix_budget_mb"))
            scene.effects.idleMatrixBudgetMB =
                nonNegative(value["idle_matrix_budget_mb"], child(path, "idle_matrix_budget_mb"),
                            "a number of megabytes >= 0");
        if (value.contains("surface_seeds"))
            scene.effects.surfaceSeeds = boolean(value["surface_seeds"], child(path, "surface_seeds"));
        if (value.contains("estimator_surface_fronts"))
            scene.effects.estimatorSurfaceFronts =
                boolean(value["estimator_surface_fronts"], child(path, "estimator_surface_fronts"));
        if (value.contains("fragment_sleeping"))
            scene.effects.fragmentSleeping =
                boolean(value["fragment_sleeping"], child(path, "fragment_sleeping"));
        if (value.contains("fracture")) {
            const Json& fracture = value["fracture"];
            const std::string fpath = child(path, "fracture");
            requireObject(fracture, fpath, "an object {\"<body name>\": true | false | {...}, ...}");
            for (const auto& item : fracture.items()) {
                const std::string bpath = child(fpath, item.key());
                auto body = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                                         [&](const SceneBody& b) { return b.name == item.key(); });
                if (body == scene.bodies.end()) {
                    std::string names;
                    for (const SceneBody& b : scene.bodies) names += (names.empty() ? "" : ", ") + b.name;
                    fail(bpath, "no body named '" + item.key() + "' (bodies: " + names + ")");
                }
                bodyFracture(item.value(), bpath, *body);
                if (body->fracture.fracturable &&
                    (body->isStatic() || body->motion == SceneMotion::Kinematic))
                    fail(bpath, "body '" + body->name + "' is " +
                                    (body->isStatic() ? "static" : "kinematic") +
                                    " and cannot break (only dynamic bodies break)");
            }
        }
    }

    // effects.fracture.<name>: fills body.fracture (keeping the resolutions).
    void bodyFracture(const Json& value, const std::string& path, SceneBody& body) const {
        FractureBodySettings& f = body.fracture;
        if (value.is_boolean()) {
            f.fracturable = value.get<bool>();
            return;
        }
        requireObject(value, path,
                      "true, false or an object {method, hybrid_threshold, energy_bound, refracture_depth, "
                      "impulse_threshold, material_noise}");
        allowOnly(value, path,
                  {"method", "hybrid_threshold", "energy_bound", "refracture_depth", "impulse_threshold",
                   "material_noise"});
        f.fracturable = true;
        if (value.contains("method"))
            f.method = parseFractureMethod(text(value["method"], child(path, "method")),
                                           source_ + ": " + child(path, "method"));
        if (value.contains("hybrid_threshold")) {
            if (f.method != FractureMethod::Hybrid)
                fail(child(path, "hybrid_threshold"),
                     std::string("applies to method \"hybrid\" only (method is \"") + toString(f.method) +
                         "\")");
            f.hybridElementThreshold = integer(value["hybrid_threshold"], child(path, "hybrid_threshold"), 1);
        }
        if (value.contains("energy_bound"))
            f.energyBound = boolean(value["energy_bound"], child(path, "energy_bound"));
        if (value.contains("refracture_depth"))
            f.maxRefractureDepth = integer(value["refracture_depth"], child(path, "refracture_depth"), 0, 20);
        if (value.contains("impulse_threshold"))
            f.impulseThreshold =
                positive(value["impulse_threshold"], child(path, "impulse_threshold"), "N s");
        if (value.contains("material_noise")) {
            const Json& noise = value["material_noise"];
            const std::string npath = child(path, "material_noise");
            requireObject(noise, npath, "an object {\"amplitude\": a, \"wavelength\": l, \"seed\": s}");
            allowOnly(noise, npath, {"amplitude", "wavelength", "seed"});
            if (!noise.contains("amplitude"))
                fail(child(npath, "amplitude"), "missing; expected a number in [0, 1)");
            MaterialNoise& n = f.materialNoise;
            n.amplitude = number(noise["amplitude"], child(npath, "amplitude"), "a number in [0, 1)");
            if (!(n.amplitude >= 0.0 && n.amplitude < 1.0))
                fail(child(npath, "amplitude"),
                     "expected a number in [0, 1), got " + shown(noise["amplitude"]));
            if (noise.contains("wavelength"))
                n.wavelength = positive(noise["wavelength"], child(npath, "wavelength"), "m");
            if (noise.contains("seed")) n.seed = seed(noise["seed"], child(npath, "seed"));
        }
    }

    // A body's "resolution": the resolution fields of its fracture settings.
    void resolution(const Json& value, const std::string& path, FractureBodySettings& r) const {
        requireObject(value, path,
                      "an object {bem_triangles, collision_triangles, voxel_size, crack_element_size}");
        allowOnly(value, path, {"bem_triangles", "collision_triangles", "voxel_size", "crack_element_size"});
        if (value.contains("bem_triangles"))
            r.bemTriangleTarget = integer(value["bem_triangles"], child(path, "bem_triangles"), 4);
        if (value.contains("collision_triangles"))
            r.collisionTriangleTarget =
                integer(value["collision_triangles"], child(path, "collision_triangles"), 4);
        if (value.contains("voxel_size"))
            r.voxelSize = positive(value["voxel_size"], child(path, "voxel_size"), "m");
        if (value.contains("crack_element_size"))
            r.crackElementSize = nonNegative(value["crack_element_size"], child(path, "crack_element_size"),
                                             "a number >= 0 [m] (0: relative to the BEM mesh)");
        if (r.collisionTriangleTarget < r.bemTriangleTarget)
            fail(path, "collision_triangles (" + std::to_string(r.collisionTriangleTarget) +
                           ") must be >= bem_triangles (" + std::to_string(r.bemTriangleTarget) +
                           "): the BEM mesh is the coarsest resolution");
    }

    SceneShape shape(const Json& value, const std::string& path) const {
        requireObject(value, path, "an object with a \"type\"");
        if (!value.contains("type"))
            fail(child(path, "type"), "missing; expected \"mesh\", \"box\", \"sphere\" or \"plane\"");
        const std::string type = text(value["type"], child(path, "type"));
        SceneShape s;
        if (type == "mesh") {
            s.type = SceneShapeType::Mesh;
            allowOnly(value, path, {"type", "file", "collision"});
            if (!value.contains("file"))
                fail(child(path, "file"), "missing; expected the path of an .obj or .ply file");
            s.meshFile = meshPath(text(value["file"], child(path, "file")), child(path, "file"));
            if (value.contains("collision")) {
                const std::string collision = text(value["collision"], child(path, "collision"));
                if (collision == "convex_hull")
                    s.collision = SceneMeshCollision::ConvexHull;
                else if (collision == "gimpact")
                    s.collision = SceneMeshCollision::GImpact;
                else
                    fail(child(path, "collision"),
                         "expected \"convex_hull\" or \"gimpact\", got \"" + collision + "\"");
            }
        } else if (type == "box") {
            s.type = SceneShapeType::Box;
            allowOnly(value, path, {"type", "half_extents"});
            if (!value.contains("half_extents"))
                fail(child(path, "half_extents"), "missing; expected 3 half extents [m]");
            s.halfExtents = vector3(value["half_extents"], child(path, "half_extents"), "m");
            if (!(s.halfExtents.minCoeff() > 0.0))
                fail(child(path, "half_extents"),
                     "expected 3 positive half extents [m], got " + shown(value["half_extents"]));
        } else if (type == "sphere") {
            s.type = SceneShapeType::Sphere;
            allowOnly(value, path, {"type", "radius"});
            if (!value.contains("radius")) fail(child(path, "radius"), "missing; expected the radius [m]");
            s.radius = positive(value["radius"], child(path, "radius"), "m");
        } else if (type == "plane") {
            s.type = SceneShapeType::Plane;
            allowOnly(value, path, {"type", "normal", "offset"});
            if (value.contains("normal")) s.normal = vector3(value["normal"], child(path, "normal"), "");
            const double length = s.normal.norm();
            if (!(length > 1e-12))
                fail(child(path, "normal"),
                     "expected a non-zero normal vector, got " + shown(value["normal"]));
            if (std::abs(length - 1.0) > 1e-9)
                logf(LogLevel::Info, source_, ": ", child(path, "normal"),
                     ": normalised the plane normal (length ", length, ")");
            s.normal /= length;
            if (value.contains("offset"))
                s.offset = number(value["offset"], child(path, "offset"), "a number [m]");
        } else {
            fail(child(path, "type"),
                 "expected \"mesh\", \"box\", \"sphere\" or \"plane\", got \"" + type + "\"");
        }
        return s;
    }

    std::string meshPath(const std::string& file, const std::string& path) const {
        if (file.empty()) fail(path, "expected the path of an .obj or .ply file, got \"\"");
        std::filesystem::path resolved(file);
        if (resolved.is_relative() && !baseDirectory_.empty())
            resolved = std::filesystem::path(baseDirectory_) / resolved;
        resolved = resolved.lexically_normal();
        std::error_code error;
        if (!std::filesystem::is_regular_file(resolved, error))
            fail(path, "mesh file '" + resolved.string() +
                           "' not found (relative paths are taken from the scene's folder)");
        return resolved.string();
    }

    Eigen::Quaterniond orientation(const Json& value, const std::string& path) const {
        requireObject(value, path, "{\"axis\": [x, y, z], \"degrees\": a} or {\"quaternion\": [w, x, y, z]}");
        allowOnly(value, path, {"axis", "degrees", "quaternion"});
        if (value.contains("quaternion")) {
            if (value.contains("axis") || value.contains("degrees"))
                fail(path, "give either \"quaternion\" or \"axis\" + \"degrees\", not both");
            const Json& q = value["quaternion"];
            const std::string qpath = child(path, "quaternion");
            if (!q.is_array() || q.size() != 4) fail(qpath, "expected [w, x, y, z], got " + shown(q));
            Eigen::Quaterniond r(
                number(q[0], element(qpath, 0), "a number"), number(q[1], element(qpath, 1), "a number"),
                number(q[2], element(qpath, 2), "a number"), number(q[3], element(qpath, 3), "a number"));
            const double norm = r.norm();
            if (!(norm > 1e-12)) fail(qpath, "expected a non-zero quaternion, got " + shown(q));
            if (std::abs(norm - 1.0) > 1e-9)
                logf(LogLevel::Info, source_, ": ", qpath, ": normalised the quaternion (norm ", norm, ")");
            return r.normalized();
        }
        if (!value.contains("axis") || !value.contains("degrees"))
            fail(path,
                 "expected {\"axis\": [x, y, z], \"degrees\": a} or {\"quaternion\": [w, x, y, z]}, got " +
                     shown(value));
        const Eigen::Vector3d axis = vector3(value["axis"], child(path, "axis"), "");
        if (!(axis.norm() > 1e-12))
            fail(child(path, "axis"), "expected a non-zero axis, got " + shown(value["axis"]));
        const double degrees = number(value["degrees"], child(path, "degrees"), "an angle [degrees]");
        // The rotation by `degrees` about `axis`: (cos(a/2), sin(a/2) axis).
        const double half = 0.5 * (degrees * M_PI / 180.0);
        const Eigen::Vector3d v = pmath::sin(half) * axis.normalized();
        return Eigen::Quaterniond(pmath::cos(half), v.x(), v.y(), v.z());
    }

    Material material(const Json& value, const std::string& path, const std::string& bodyName) const {
        try {
            if (value.is_string()) return Material::preset(value.get<std::string>());
            requireObject(
                value, path,
                "a preset name or an object {E, nu, density, strength, toughness, compressive_factor}");
            allowOnly(value, path,
                      {"preset", "E", "nu", "density", "strength", "toughness", "compressive_factor"});
            std::optional<Material> base;
            if (value.contains("preset"))
                base = Material::preset(text(value["preset"], child(path, "preset")));
            auto field = [&](const char* key, const std::string& unit, double fallback) {
                if (value.contains(key))
                    return number(value[key], child(path, key), "a number [" + unit + "]");
                if (!base)
                    fail(child(path, key),
                         "missing; give all of E, nu, density, strength, toughness, compressive_factor, "
                         "or a \"preset\" to start from");
                return fallback;
            };
            const Material m = base ? *base : Material::steel();
            // A preset keeps its name only when nothing overrides it; otherwise the body names it.
            const std::string name = base && value.size() == 1 ? base->name() : bodyName;
            const double E = field("E", "Pa", m.youngsModulus());
            const double nu = field("nu", "-", m.poissonRatio());
            const double density = field("density", "kg/m^3", m.density());
            const double strength = field("strength", "Pa", m.tensileStrength());
            const double toughness = field("toughness", "Pa m^1/2", m.fractureToughness());
            const double compressive = field("compressive_factor", "-", m.compressiveFactor());
            return Material(E, nu, density, strength, toughness, compressive, name);
        } catch (const Error& e) {
            const std::string message = e.what();
            if (message.rfind(source_ + ": ", 0) == 0) throw;  // already names file and key
            fail(path, message);
        }
    }

    SceneBody body(const Json& value, const std::string& path, size_t index) const {
        requireObject(value, path, "a body object");
        allowOnly(value, path,
                  {"name", "shape", "scale", "position", "orientation", "linear_velocity", "angular_velocity",
                   "density", "mass", "material", "state", "friction", "restitution", "resolution"});
        SceneBody b;
        b.name = value.contains("name") ? text(value["name"], child(path, "name"))
                                        : "body" + std::to_string(index);
        if (b.name.empty() ||
            std::any_of(b.name.begin(), b.name.end(), [](unsigned char c) { return std::isspace(c); }))
            fail(child(path, "name"), "expected a non-empty name without spaces, got \"" + b.name + "\"");
        if (!value.contains("shape"))
            fail(child(path, "shape"),
                 "missing; expected {\"type\": \"mesh\" | \"box\" | \"sphere\" | \"plane\", ...}");
        b.shape = shape(value["shape"], child(path, "shape"));

        if (b.shape.type == SceneShapeType::Plane)
            for (const char* key : {"scale", "position", "orientation", "linear_velocity", "angular_velocity",
                                    "density", "state", "resolution"})
                if (value.contains(key))
                    fail(child(path, key),
                         "not allowed for a plane (a plane is static and placed by its normal and offset)");

        if (value.contains("scale")) {
            const Json& scale = value["scale"];
            const std::string spath = child(path, "scale");
            b.scale = scale.is_number() ? Eigen::Vector3d::Constant(number(scale, spath, "a number"))
                                        : vector3(scale, spath, "");
            if (!(b.scale.minCoeff() > 0.0))
                fail(spath, "expected a positive number or 3 positive numbers, got " + shown(scale));
            if (b.shape.type == SceneShapeType::Sphere && b.scale.maxCoeff() != b.scale.minCoeff())
                fail(spath, "a sphere takes one uniform scale, got " + shown(scale));
        }
        if (value.contains("position")) b.position = vector3(value["position"], child(path, "position"), "m");
        if (value.contains("orientation"))
            b.orientation = orientation(value["orientation"], child(path, "orientation"));
        if (value.contains("linear_velocity"))
            b.linearVelocity = vector3(value["linear_velocity"], child(path, "linear_velocity"), "m/s");
        if (value.contains("angular_velocity"))
            b.angularVelocity = vector3(value["angular_velocity"], child(path, "angular_velocity"), "rad/s");
        if (value.contains("material"))
            b.material = material(value["material"], child(path, "material"), b.name);
        if (value.contains("friction"))
            b.friction = nonNegative(value["friction"], child(path, "friction"), "a number >= 0");
        if (value.contains("restitution")) {
            b.restitution = number(value["restitution"], child(path, "restitution"), "a number in [0, 1]");
            if (!(b.restitution >= 0.0 && b.restitution <= 1.0))
                fail(child(path, "restitution"),
                     "expected a number in [0, 1], got " + shown(value["restitution"]));
        }
        if (value.contains("resolution"))
            resolution(value["resolution"], child(path, "resolution"), b.fracture);
        if (value.contains("state")) {
            b.motion = static_cast<SceneMotion>(
                choice(value["state"], child(path, "state"), {"dynamic", "sleeping", "kinematic"}));
            if (b.motion == SceneMotion::Kinematic)
                for (const char* key : {"mass", "density"})
                    if (value.contains(key))
                        fail(child(path, key), "not allowed for a kinematic body (it has infinite mass)");
        }

        if (value.contains("density") && value.contains("mass"))
            fail(path, "give either \"density\" or \"mass\", not both");
        b.density = value.contains("density") ? positive(value["density"], child(path, "density"), "kg/m^3")
                                              : b.material.density();
        if (value.contains("mass")) {
            const double mass =
                nonNegative(value["mass"], child(path, "mass"), "a mass >= 0 [kg] (0 = static)");
            if (b.shape.type == SceneShapeType::Plane && mass != 0.0)
                fail(child(path, "mass"), "a plane is always static (mass 0), got " + shown(value["mass"]));
            b.mass = mass;
        }
        if (b.isStatic() && (b.linearVelocity.squaredNorm() > 0.0 || b.angularVelocity.squaredNorm() > 0.0))
            fail(path,
                 "a static body (mass 0 or plane) cannot have a velocity; use \"state\": \"kinematic\"");
        if (b.isStatic() && b.motion == SceneMotion::Sleeping)
            fail(child(path, "state"), "a static body (mass 0) cannot be \"sleeping\"");
        return b;
    }

    std::string source_;
    std::string baseDirectory_;
};

// Parses JSON, rejecting duplicate keys (nlohmann would keep the last one silently).
Json parseJson(const std::string& text, const std::string& source) {
    std::vector<std::set<std::string>> openObjects;
    auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) openObjects.emplace_back();
        if (event == Json::parse_event_t::object_end) openObjects.pop_back();
        if (event == Json::parse_event_t::key && !openObjects.back().insert(parsed.get<std::string>()).second)
            throw Error(source + ": duplicate key \"" + parsed.get<std::string>() + "\"");
        return true;
    };
    try {
        return Json::parse(text, callback);
    } catch (const Json::exception& e) {  // parse_error, and out_of_range for numbers like 1e999
        std::string message = e.what();
        const size_t bracket = message.find("] ");
        if (message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            message = message.substr(bracket + 2);
        throw Error(source + ": invalid JSON: " + message);
    }
}

}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& source, const std::string& baseDirectory) {
    Scene scene = SceneParser(source, baseDirectory).parse(parseJson(jsonText, source));
    scene.file = source;
    scene.name = std::filesystem::path(source).stem().string();
    return scene;
}

Scene readSceneFile(const std::string& path) {
    return parseScene(readWholeFile(path, "scene file"), path,
                      std::filesystem::path(path).parent_path().string());
}

}  // namespace btfracture
