// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/io/SceneFile.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace btfracture;

namespace {

const std::string kMeshes = BTFRACTURE_MESH_DIR;
const std::string kScenes = std::string(BTFRACTURE_MESH_DIR) + "/../scenes";

// A valid scene with one body whose JSON text is `body`; parsed from "test.json" in demos/meshes.
std::string withBody(const std::string& body) {
    return R"({"bodies": [{"name": "ground", "shape": {"type": "plane"}}, )" + body + "]}";
}

std::string errorOf(const std::string& json) {
    try {
        parseScene(json, "test.json", kMeshes);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(SceneFile, DefaultsAndValues) {
    const Scene s = parseScene(withBody(R"({"name": "rock", "shape": {"type": "mesh", "file": "bunny.obj"},
        "scale": [1, 2, 3], "position": [1, 2, 3], "linear_velocity": [0, 0, -4], "angular_velocity": [0, 1, 0],
        "material": "glass"})"),
                               "dir/test.json", kMeshes);
    EXPECT_EQ(s.name, "test");
    EXPECT_EQ(s.world.gravity, Eigen::Vector3d(0, -9.81, 0));
    EXPECT_DOUBLE_EQ(s.world.dt, 1.0 / 240.0);
    EXPECT_EQ(s.world.steps, 240);
    EXPECT_EQ(s.world.substeps, 1);
    EXPECT_FALSE(s.effects.fragmentSleeping);
    EXPECT_EQ(s.outputs.objEveryNSteps, 10);
    EXPECT_EQ(s.outputs.motionEveryNSteps, 10);
    ASSERT_EQ(s.bodies.size(), 2u);
    EXPECT_TRUE(s.bodies[0].isStatic());
    EXPECT_EQ(s.bodies[0].material.name(), "steel");  // the default material
    const SceneBody& rock = s.bodies[1];
    EXPECT_EQ(rock.shape.type, SceneShapeType::Mesh);
    EXPECT_EQ(rock.shape.collision, SceneMeshCollision::ConvexHull);
    EXPECT_EQ(rock.shape.meshFile, kMeshes + "/bunny.obj");  // relative to the scene's folder
    EXPECT_EQ(rock.scale, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(rock.linearVelocity, Eigen::Vector3d(0, 0, -4));
    EXPECT_EQ(rock.material.name(), "glass");
    EXPECT_DOUBLE_EQ(rock.density, 2500.0);  // from the material
    EXPECT_FALSE(rock.mass.has_value());
    EXPECT_FALSE(rock.isStatic());
    EXPECT_FALSE(rock.fracture.fracturable);  // no effects section: nothing breaks
    EXPECT_EQ(rock.motion, SceneMotion::Dynamic);
    EXPECT_DOUBLE_EQ(rock.friction, 0.5);
    EXPECT_DOUBLE_EQ(rock.restitution, 0.0);
    EXPECT_EQ(rock.fracture.bemTriangleTarget, 1000);
    EXPECT_EQ(rock.fracture.collisionTriangleTarget, 5000);
    EXPECT_EQ(rock.fracture.voxelSize, 0.0);
    // Without an effects section a run writes the meshes once, motion.csv and scene.glb.
    EXPECT_TRUE(s.effects.outputs.motion && s.effects.outputs.gltf);
    EXPECT_FALSE(s.effects.outputs.obj || s.effects.outputs.csv || s.effects.outputs.png ||
                 s.effects.outputs.vdb);
    EXPECT_EQ(s.effects.seed, 0u);
    EXPECT_TRUE(s.effects.voxelFronts);  // the marker cut
    EXPECT_EQ(s.outputs.pngEveryNSteps, 10);
    EXPECT_EQ(s.outputs.image.width, 640);
}

TEST(SceneFile, EffectsResolutionsAndMotion) {
    const Scene s = parseScene(R"({"bodies": [
        {"name": "ground", "shape": {"type": "plane"}, "friction": 0.8},
        {"name": "pane", "shape": {"type": "box", "half_extents": [0.5, 0.5, 0.005]}, "material": "glass",
         "resolution": {"bem_triangles": 600, "collision_triangles": 2400, "voxel_size": 0.002,
                        "crack_element_size": 0.01}},
        {"name": "rock", "shape": {"type": "sphere", "radius": 0.1}, "state": "sleeping", "restitution": 0.25},
        {"name": "pusher", "shape": {"type": "box", "half_extents": [0.1, 0.1, 0.1]}, "state": "kinematic",
         "linear_velocity": [1, 0, 0]}],
      "outputs": {"png_every_n_steps": 5,
                  "image": {"width": 320, "height": 200, "projection": "orthographic", "shading": "flat",
                            "view": [0, 1, 0]}},
      "effects": {"outputs": ["png", "csv", "obj"], "seed": 42, "crack_cut": "coarse_sheet",
                  "idle_matrix_budget_mb": 64, "surface_seeds": true, "estimator_surface_fronts": true, "fragment_sleeping": true,
                  "fracture": {"pane": {"method": "hybrid", "hybrid_threshold": 3000, "energy_bound": false, "refracture_depth": 2,
                                        "impulse_threshold": 0.5,
                                        "material_noise": {"amplitude": 0.2, "seed": 7}},
                               "rock": {"method": "est"}}}})",
                               "test.json", kMeshes);
    EXPECT_DOUBLE_EQ(s.bodies[0].friction, 0.8);
    const SceneBody& pane = s.bodies[1];
    EXPECT_EQ(pane.fracture.bemTriangleTarget, 600);
    EXPECT_EQ(pane.fracture.collisionTriangleTarget, 2400);
    EXPECT_DOUBLE_EQ(pane.fracture.voxelSize, 0.002);
    EXPECT_DOUBLE_EQ(pane.fracture.crackElementSize, 0.01);
    EXPECT_TRUE(pane.fracture.fracturable);
    EXPECT_EQ(pane.fracture.method, FractureMethod::Hybrid);
    EXPECT_FALSE(pane.fracture.energyBound);
    EXPECT_EQ(pane.fracture.hybridElementThreshold, 3000);
    EXPECT_EQ(pane.fracture.maxRefractureDepth, 2);
    EXPECT_DOUBLE_EQ(pane.fracture.impulseThreshold, 0.5);
    EXPECT_DOUBLE_EQ(pane.fracture.materialNoise.amplitude, 0.2);
    EXPECT_EQ(pane.fracture.materialNoise.seed, 7u);
    const SceneBody& rock = s.bodies[2];
    EXPECT_TRUE(rock.fracture.fracturable);
    EXPECT_EQ(rock.fracture.method, FractureMethod::Estimated);
    EXPECT_EQ(rock.fracture.maxRefractureDepth, 3);         // default
    EXPECT_TRUE(rock.fracture.energyBound);                 // default
    EXPECT_DOUBLE_EQ(rock.fracture.crackElementSize, 0.0);  // default: relative to the BEM mesh
    EXPECT_EQ(rock.motion, SceneMotion::Sleeping);
    EXPECT_DOUBLE_EQ(rock.restitution, 0.25);
    EXPECT_EQ(s.bodies[3].motion, SceneMotion::Kinematic);
    EXPECT_FALSE(s.bodies[3].isStatic());
    EXPECT_FALSE(s.bodies[3].fracture.fracturable);
    EXPECT_TRUE(s.effects.outputs.obj && s.effects.outputs.csv && s.effects.outputs.png);
    EXPECT_FALSE(s.effects.outputs.vdb || s.effects.outputs.motion || s.effects.outputs.gltf);
    EXPECT_EQ(s.effects.seed, 42u);
    EXPECT_DOUBLE_EQ(s.effects.idleMatrixBudgetMB, 64.0);
    EXPECT_TRUE(s.effects.surfaceSeeds);
    EXPECT_TRUE(s.effects.estimatorSurfaceFronts);
    EXPECT_TRUE(s.effects.fragmentSleeping);
    EXPECT_FALSE(s.effects.voxelFronts);
    EXPECT_EQ(s.outputs.pngEveryNSteps, 5);
    EXPECT_EQ(s.outputs.image.width, 320);
    EXPECT_EQ(s.outputs.image.height, 200);
    EXPECT_EQ(s.outputs.image.projection, Projection::Orthographic);
    EXPECT_EQ(s.outputs.image.shading, Shading::Flat);

    // --method overrides every breakable body and leaves the others alone.
    Scene overridden = s;
    overrideFractureMethod(overridden, FractureMethod::Full);
    EXPECT_EQ(overridden.bodies[1].fracture.method, FractureMethod::Full);
    EXPECT_EQ(overridden.bodies[2].fracture.method, FractureMethod::Full);
    EXPECT_EQ(parseFractureMethod("est", "--method"), FractureMethod::Estimated);
    try {
        parseFractureMethod("fast", "--method");
        ADD_FAILURE() << "unknown method accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), R"(--method: expected "full", "est" or "hybrid", got "fast")");
    }
}

TEST(SceneFile, BadEffectsNameTheirPath) {
    const std::string bodies = R"("bodies": [{"name": "ground", "shape": {"type": "plane"}},
        {"name": "ball", "shape": {"type": "sphere", "radius": 1}}])";
    const std::pair<std::string, std::string> cases[] = {
        {R"("effects": {"outputs": ["obj", "gif"]})",
         R"(test.json: effects.outputs[1]: expected "motion", "gltf", "obj", "vdb", "csv" or "png", got "gif")"},
        {R"("effects": {"outputs": ["png", "png"]})",
         R"(test.json: effects.outputs[1]: listed twice: "png")"},
        {R"("effects": {"outputs": "png"})", "test.json: effects.outputs: expected an array of"},
        {R"("effects": {"seed": -3})", "test.json: effects.seed: expected an integer seed >= 0, got -3"},
        {R"("effects": {"crack_cut": "voxels"})",
         R"(test.json: effects.crack_cut: expected "markers" or "coarse_sheet", got "voxels")"},
        {R"("effects": {"fracture": {"bal": true}})",
         "test.json: effects.fracture.bal: no body named 'bal' (bodies: ground, ball)"},
        {R"("effects": {"fracture": {"ground": true}})",
         "test.json: effects.fracture.ground: body 'ground' is static and cannot break"},
        {R"("effects": {"fracture": {"ball": "yes"}})",
         R"(test.json: effects.fracture.ball: expected true, false or an object {method, hybrid_threshold,)"},
        {R"("effects": {"fracture": {"ball": {"methd": "est"}}})",
         "test.json: effects.fracture.ball.methd: unknown key (expected one of: method, hybrid_threshold,"},
        {R"("effects": {"fracture": {"ball": {"method": "fast"}}})",
         R"(test.json: effects.fracture.ball.method: expected "full", "est" or "hybrid", got "fast")"},
        {R"("effects": {"fracture": {"ball": {"method": "full", "hybrid_threshold": 10}}})",
         R"(test.json: effects.fracture.ball.hybrid_threshold: applies to method "hybrid" only (method is "full"))"},
        {R"("effects": {"fracture": {"ball": {"energy_bound": 1}}})",
         "test.json: effects.fracture.ball.energy_bound: expected true or false, got 1"},
        {R"("effects": {"fracture": {"ball": {"refracture_depth": 99}}})",
         "test.json: effects.fracture.ball.refracture_depth: expected an integer in [0, 20], got 99"},
        {R"("effects": {"fracture": {"ball": {"material_noise": {"amplitude": 1.5}}}})",
         "test.json: effects.fracture.ball.material_noise.amplitude: expected a number in [0, 1), got 1.5"},
        {R"("effects": {"fracture": {"ball": {"material_noise": {"seed": 1}}}})",
         "test.json: effects.fracture.ball.material_noise.amplitude: missing"},
        {R"("effects": {"fracture": {"ball": {"impulse_threshold": 0}}})",
         "test.json: effects.fracture.ball.impulse_threshold: expected a positive number [N s], got 0"},
        {R"("effects": {"fractures": {}})",
         "test.json: effects.fractures: unknown key (expected one of: outputs, seed, crack_cut, "
         "idle_matrix_budget_mb, surface_seeds, estimator_surface_fronts, fragment_sleeping, fracture)"},
        {R"("effects": {"estimator_surface_fronts": 0})",
         "test.json: effects.estimator_surface_fronts: expected true or false, got 0"},
        {R"("effects": {"fragment_sleeping": 1})",
         "test.json: effects.fragment_sleeping: expected true or false, got 1"},
        {R"("effects": {"surface_seeds": "yes"})",
         "test.json: effects.surface_seeds: expected true or false, got \"yes\""},
        {R"("effects": {"idle_matrix_budget_mb": -5})",
         "test.json: effects.idle_matrix_budget_mb: expected a number of megabytes >= 0, got -5"},
        {R"("outputs": {"image": {"width": 8}})",
         "test.json: outputs.image.width: expected an integer in [16, 8192], got 8"},
        {R"("outputs": {"image": {"projection": "fisheye"}})",
         R"(test.json: outputs.image.projection: expected "perspective" or "orthographic", got "fisheye")"},
        {R"("outputs": {"image": {"view": [0, 0, 0]}})",
         "test.json: outputs.image.view: expected a non-zero direction, got [0,0,0]"},
    };
    for (const auto& [section, expected] : cases) {
        const std::string message = errorOf("{" + bodies + ", " + section + "}");
        EXPECT_TRUE(contains(message, expected)) << "expected: " << expected << "\n     got: " << message;
    }
}

TEST(SceneFile, OrientationsAndMaterials) {
    const Scene s = parseScene(withBody(R"({"name": "a", "shape": {"type": "box", "half_extents": [1, 1, 1]},
        "orientation": {"axis": [0, 2, 0], "degrees": 90}, "mass": 3,
        "material": {"preset": "pmma", "strength": 4e6}}, {"name": "b", "shape": {"type": "sphere", "radius": 1},
        "orientation": {"quaternion": [2, 0, 0, 0]}, "density": 10, "scale": 2,
        "material": {"E": 1e9, "nu": 0.3, "density": 900, "strength": 1e6, "toughness": 2e5, "compressive_factor": 3}})"),
                               "test.json", kMeshes);
    const SceneBody& a = s.bodies[1];
    // 90 degrees about +y turns +x into -z.
    EXPECT_LT((a.orientation * Eigen::Vector3d::UnitX() - Eigen::Vector3d(0, 0, -1)).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(*a.mass, 3.0);
    EXPECT_DOUBLE_EQ(a.material.tensileStrength(), 4e6);
    EXPECT_DOUBLE_EQ(a.material.youngsModulus(), 3.1e9);  // the rest from the preset
    EXPECT_EQ(a.material.name(), "a");                    // modified preset: named after the body
    const SceneBody& b = s.bodies[2];
    EXPECT_DOUBLE_EQ(b.orientation.w(), 1.0);  // normalised
    EXPECT_DOUBLE_EQ(b.density, 10.0);         // the body's density wins over the material's
    EXPECT_DOUBLE_EQ(b.material.density(), 900.0);
    EXPECT_DOUBLE_EQ(b.material.compressiveFactor(), 3.0);
    EXPECT_EQ(b.scale, Eigen::Vector3d::Constant(2.0));
}

TEST(SceneFile, UnknownKeysNameTheirPath) {
    EXPECT_TRUE(contains(
        errorOf(withBody(R"({"name": "b", "shape": {"type": "sphere", "radius": 1}, "velocty": [1, 0, 0]})")),
        "test.json: bodies[1].velocty: unknown key (expected one of: name, shape, scale,"));
    EXPECT_TRUE(contains(
        errorOf(R"({"world": {"dt": 0.01, "gravty": [0, 0, 0]}, "bodies": [{"shape": {"type": "plane"}}]})"),
        "test.json: world.gravty: unknown key (expected one of: gravity, dt, steps, substeps)"));
    EXPECT_TRUE(contains(
        errorOf(withBody(R"({"shape": {"type": "sphere", "radius": 1, "half_extents": [1, 1, 1]}})")),
        "test.json: bodies[1].shape.half_extents: unknown key (expected one of: type, radius)"));
    EXPECT_TRUE(contains(
        errorOf(withBody(
            R"({"shape": {"type": "box", "half_extents": [1, 1, 1]}, "material": {"E": 1, "youngs": 2}})")),
        "test.json: bodies[1].material.youngs: unknown key"));
    EXPECT_TRUE(contains(errorOf(R"({"bodies": [{"shape": {"type": "plane"}}], "output": {}})"),
                         "test.json: output: unknown key (expected one of: $schema, description, world, "
                         "bodies, outputs, effects)"));
}

TEST(SceneFile, WrongTypesAndBadValues) {
    const std::pair<std::string, std::string> cases[] = {
        {R"({"world": {"dt": "fast"}, "bodies": [{"shape": {"type": "plane"}}]})",
         R"(test.json: world.dt: expected a positive number [s], got "fast")"},
        {R"({"world": {"dt": -0.01}, "bodies": [{"shape": {"type": "plane"}}]})",
         "test.json: world.dt: expected a positive number [s], got -0.01"},
        {R"({"world": {"steps": 2.5}, "bodies": [{"shape": {"type": "plane"}}]})",
         "test.json: world.steps: expected an integer >= 0, got 2.5"},
        {R"({"world": {"substeps": 0}, "bodies": [{"shape": {"type": "plane"}}]})",
         "test.json: world.substeps: expected an integer >= 1, got 0"},
        {R"({"world": {"gravity": [0, -9.81]}, "bodies": [{"shape": {"type": "plane"}}]})",
         "test.json: world.gravity: expected an array of 3 numbers [m/s^2], got [0,-9.81]"},
        {R"({"bodies": []})", "test.json: bodies: expected a non-empty array of bodies, got []"},
        {R"({"world": {}})", "test.json: bodies: missing; expected an array of bodies"},
        {R"([1, 2])", "test.json: expected the scene (a JSON object), got [1,2]"},
        {withBody(R"({"shape": {"type": "sphere", "radius": -0.2}})"),
         "test.json: bodies[1].shape.radius: expected a positive number [m], got -0.2"},
        {withBody(R"({"shape": {"type": "cone"}})"),
         R"(test.json: bodies[1].shape.type: expected "mesh", "box", "sphere" or "plane", got "cone")"},
        {withBody(R"({"shape": {"type": "box", "half_extents": [1, 0, 1]}})"),
         "test.json: bodies[1].shape.half_extents: expected 3 positive half extents [m], got [1,0,1]"},
        {withBody(R"({"shape": {"type": "mesh", "file": "bunny.obj", "collision": "bvh"}})"),
         R"(test.json: bodies[1].shape.collision: expected "convex_hull" or "gimpact", got "bvh")"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "fracturable": true})"),
         "test.json: bodies[1].fracturable: unknown key"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "resolution": {"bem_triangles": 900,
            "collision_triangles": 400}})"),
         "test.json: bodies[1].resolution: collision_triangles (400) must be >= bem_triangles (900)"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "resolution": {"voxel_size": -1}})"),
         "test.json: bodies[1].resolution.voxel_size: expected a positive number [m], got -1"},
        {withBody(
             R"({"shape": {"type": "sphere", "radius": 1}, "resolution": {"crack_element_size": -0.01}})"),
         "test.json: bodies[1].resolution.crack_element_size: expected a number >= 0 [m] (0: relative to "
         "the BEM mesh), got -0.01"},
        {withBody(
             R"({"shape": {"type": "sphere", "radius": 1}, "resolution": {"crack_element_size": "fine"}})"),
         "test.json: bodies[1].resolution.crack_element_size: expected a number >= 0 [m] (0: relative to "
         "the BEM mesh), got \"fine\""},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "resolution": {"bem_triangles": 2}})"),
         "test.json: bodies[1].resolution.bem_triangles: expected an integer >= 4, got 2"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "state": "frozen"})"),
         R"(test.json: bodies[1].state: expected "dynamic", "sleeping" or "kinematic", got "frozen")"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "state": "kinematic", "mass": 3})"),
         "test.json: bodies[1].mass: not allowed for a kinematic body (it has infinite mass)"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "mass": 0, "state": "sleeping"})"),
         R"(test.json: bodies[1].state: a static body (mass 0) cannot be "sleeping")"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "friction": -0.1})"),
         "test.json: bodies[1].friction: expected a number >= 0, got -0.1"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "restitution": 1.5})"),
         "test.json: bodies[1].restitution: expected a number in [0, 1], got 1.5"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "scale": [1, 2, 1]})"),
         "test.json: bodies[1].scale: a sphere takes one uniform scale, got [1,2,1]"},
        {withBody(R"({"shape": {"type": "box", "half_extents": [1, 1, 1]}, "scale": -1})"),
         "test.json: bodies[1].scale: expected a positive number or 3 positive numbers, got -1"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "density": 1})"),
         R"(test.json: bodies[1]: give either "density" or "mass", not both)"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "mass": -1})"),
         "test.json: bodies[1].mass: expected a mass >= 0 [kg] (0 = static), got -1"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "mass": 0, "linear_velocity": [1, 0, 0]})"),
         "test.json: bodies[1]: a static body (mass 0 or plane) cannot have a velocity"},
        {R"({"bodies": [{"shape": {"type": "plane"}, "position": [0, 1, 0]}]})",
         "test.json: bodies[0].position: not allowed for a plane"},
        {R"({"bodies": [{"shape": {"type": "plane", "normal": [0, 0, 0]}}]})",
         "test.json: bodies[0].shape.normal: expected a non-zero normal vector, got [0,0,0]"},
        {withBody(R"({"shape": {"type": "sphere", "radius": 1}, "orientation": {"axis": [0, 1, 0]}})"),
         "test.json: bodies[1].orientation: expected {\"axis\": [x, y, z], \"degrees\": a} or "
         "{\"quaternion\": [w, x, y, z]}"},
        {withBody(
             R"({"shape": {"type": "sphere", "radius": 1}, "orientation": {"quaternion": [0, 0, 0, 0]}})"),
         "test.json: bodies[1].orientation.quaternion: expected a non-zero quaternion"},
        {withBody(R"({"name": "ground", "shape": {"type": "sphere", "radius": 1}})"),
         "test.json: bodies[1].name: body name 'ground' is used twice"},
        {withBody(R"({"name": "my ball", "shape": {"type": "sphere", "radius": 1}})"),
         R"(test.json: bodies[1].name: expected a non-empty name without spaces, got "my ball")"},
        {R"({"bodies": [{"shape": {"type": "plane"}}], "outputs": {"obj_every_n_steps": -1}})",
         "test.json: outputs.obj_every_n_steps: expected an integer >= 0, got -1"},
    };
    for (const auto& [json, expected] : cases) {
        const std::string message = errorOf(json);
        EXPECT_TRUE(contains(message, expected)) << "expected: " << expected << "\n     got: " << message;
    }
}

TEST(SceneFile, BadMaterialValuesNameTheKey) {
    const std::pair<std::string, std::string> cases[] = {
        {R"({"E": -1, "nu": 0.3, "density": 900, "strength": 1e6, "toughness": 2e5, "compressive_factor": 3})",
         "test.json: bodies[1].material: material 'rock': Young's modulus E must be positive and finite, got "
         "-1 Pa"},
        {R"({"preset": "glass", "nu": 0.5})",
         "test.json: bodies[1].material: material 'rock': Poisson ratio nu must lie in (-1, 0.5), got 0.5"},
        {R"({"preset": "glass", "toughness": 0})",
         "test.json: bodies[1].material: material 'rock': fracture toughness"},
        {R"({"preset": "glass", "strength": "high"})",
         R"(test.json: bodies[1].material.strength: expected a number [Pa], got "high")"},
        {R"({"E": 1e9, "nu": 0.3})",
         "test.json: bodies[1].material.density: missing; give all of E, nu, density"},
        {R"("granite")",
         "test.json: bodies[1].material: unknown material preset 'granite'; known presets: glass concrete "
         "pmma steel"},
        {R"(42)",
         "test.json: bodies[1].material: expected a preset name or an object {E, nu, density, strength, "
         "toughness, "
         "compressive_factor}, got 42"},
    };
    for (const auto& [material, expected] : cases) {
        const std::string message = errorOf(withBody(
            R"({"name": "rock", "shape": {"type": "sphere", "radius": 1}, "material": )" + material + "}"));
        EXPECT_TRUE(contains(message, expected)) << "expected: " << expected << "\n     got: " << message;
    }
}

TEST(SceneFile, MissingFilesAndBrokenJson) {
    const std::string missing =
        errorOf(withBody(R"({"shape": {"type": "mesh", "file": "../meshes/nope.obj"}})"));
    const std::string tried =
        std::filesystem::path(kMeshes + "/../meshes/nope.obj").lexically_normal().string();
    EXPECT_TRUE(contains(missing, "test.json: bodies[1].shape.file: mesh file '" + tried + "' not found"))
        << missing;

    const std::string syntax = errorOf("{\"bodies\": [\n  {\"shape\": }\n]}");
    EXPECT_TRUE(contains(syntax, "test.json: invalid JSON: parse error at line 2, column 13")) << syntax;
    // nlohmann reports numbers beyond double range as out_of_range, not parse_error (a fuzzing find).
    const std::string overflow =
        errorOf(R"({"world": {"dt": 1e999}, "bodies": [{"shape": {"type": "plane"}}]})");
    EXPECT_TRUE(contains(overflow, "test.json: invalid JSON: number overflow parsing '1e999'")) << overflow;
    EXPECT_TRUE(
        contains(errorOf(R"({"world": {"dt": 0.1, "dt": 0.2}, "bodies": [{"shape": {"type": "plane"}}]})"),
                 "test.json: duplicate key \"dt\""));
    try {
        readSceneFile("no/such/scene.json");
        ADD_FAILURE() << "missing scene accepted";
    } catch (const Error& e) {
        EXPECT_TRUE(
            contains(e.what(), "cannot open scene file 'no/such/scene.json': No such file or directory"))
            << e.what();
    }
}

TEST(SceneFile, ShippedScenesParse) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "scene.schema.json") continue;
        SCOPED_TRACE(entry.path().string());
        const Scene scene = readSceneFile(entry.path().string());
        EXPECT_FALSE(scene.bodies.empty());
        ++scenes;
    }
    EXPECT_GE(scenes, 3);
    const Scene fig1 = readSceneFile(kScenes + "/column_bunny.json");
    EXPECT_EQ(fig1.name, "column_bunny");
    EXPECT_DOUBLE_EQ(fig1.world.dt, 0.004);
    ASSERT_EQ(fig1.bodies.size(), 4u);
    EXPECT_EQ(fig1.bodies[2].material.name(), "bunny");
    EXPECT_DOUBLE_EQ(fig1.bodies[2].material.fractureToughness(), 1e5);
}
