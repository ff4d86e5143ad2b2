// SPDX-License-Identifier: Zlib
#pragma once
// Scene files for the headless runner: JSON parsed and validated into a plain Scene (SI units).
// The format is documented with examples in demos/README.md; demos/scenes/scene.schema.json
// describes the same keys for editors (tests/io checks that the two agree). Every problem is a
// btfracture::Error "<file>: <key path>: <what was expected>", e.g.
//   column_bunny.json: bodies[2].shape.radius: expected a positive number [m], got -0.2
// Unknown keys are errors too, so that a typo never silently falls back to a default.
#include <btFracture/core/Material.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/dynamics/BemFractureEngine.h>
#include <btFracture/dynamics/FractureBodySettings.h>
#include <btFracture/io/RenderSettings.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace btfracture {

struct SceneWorldSettings {
    Eigen::Vector3d gravity{0.0, -9.81, 0.0};  // [m/s^2]
    double dt = 1.0 / 240.0;                   // frame step [s]
    int steps = 240;                           // frames to simulate
    int substeps = 1;                          // fixed Bullet steps per frame, each dt / substeps
};

enum class SceneShapeType { Mesh, Box, Sphere, Plane };
enum class SceneMeshCollision { ConvexHull, GImpact };
const char* toString(SceneShapeType type);
const char* toString(SceneMeshCollision collision);

struct SceneShape {
    SceneShapeType type = SceneShapeType::Box;
    std::string meshFile;  // Mesh: path of the .obj/.ply (relative paths resolved against the scene's folder)
    // Mesh given in memory instead of a file (FractureRB .bullet import), in the shape's own
    // frame; SceneWorld validates it like a file's mesh. Used when set; meshFile is then empty.
    std::shared_ptr<const TriangleMesh> meshData;
    SceneMeshCollision collision = SceneMeshCollision::ConvexHull;  // Mesh
    Eigen::Vector3d halfExtents{0.5, 0.5, 0.5};                     // Box [m], before scale
    double radius = 0.5;                                            // Sphere [m], before scale
    Eigen::Vector3d normal{0.0, 1.0, 0.0};                          // Plane: unit normal, world frame
    double offset = 0.0;  // Plane: points x with normal . x = offset [m]
};

// Parses the scene spelling of a fracture method ("full", "est", "hybrid"; core/FractureSettings.h);
// throws btfracture::Error naming `what` and the accepted words.
FractureMethod parseFractureMethod(const std::string& word, const std::string& what);

// A body's fracture settings as the scene gives them: dynamics' FractureBodySettings (what a
// btFractureRigidBody takes), except that nothing breaks unless the effects section says so.
inline FractureBodySettings unbreakable() {
    FractureBodySettings s;
    s.fracturable = false;
    return s;
}

// How a body moves: dynamic; dynamic but asleep until something touches it; kinematic (moves at
// its constant linear and angular velocity, pushes others, feels nothing).
enum class SceneMotion { Dynamic, Sleeping, Kinematic };
const char* toString(SceneMotion motion);

struct SceneBody {
    std::string name;  // unique, no whitespace; names the body in messages and output files
    SceneShape shape;
    Eigen::Vector3d scale{1.0, 1.0, 1.0};  // applied to the shape in its own frame (uniform for spheres)
    // Pose of the shape's own frame (the mesh file's coordinates) in the world.
    Eigen::Vector3d position = Eigen::Vector3d::Zero();               // [m]
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // unit
    Eigen::Vector3d linearVelocity = Eigen::Vector3d::Zero();         // of the centre of mass [m/s]
    Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();        // world frame [rad/s]
    // Mass from `mass` when given (0 = static), else from `density` times the volume.
    std::optional<double> mass;  // [kg]
    double density = 0.0;        // [kg/m^3]: the body's "density", else the material's
    Material material = Material::steel();
    SceneMotion motion = SceneMotion::Dynamic;
    double friction = 0.5;     // Bullet's friction coefficient [-]
    double restitution = 0.0;  // Bullet's restitution [-]
    // From effects.fracture.<name> (fracturable, method, hybridElementThreshold, energyBound,
    // impulseThreshold, maxRefractureDepth, materialNoise: amplitude, wavelength and the body's
    // seed, which the runner combines with SceneEffects::seed) and the body's "resolution"
    // (bemTriangleTarget, collisionTriangleTarget, voxelSize, crackElementSize).
    FractureBodySettings fracture = unbreakable();

    // Never moves: a plane or mass 0 (kinematic bodies move, so they are not static).
    bool isStatic() const {
        return motion != SceneMotion::Kinematic &&
               (shape.type == SceneShapeType::Plane || (mass && *mass == 0.0));
    }
};

struct SceneOutputs {
    std::string
        directory;  // empty: the runner's choice (out/<scene name>); relative to the working directory
    int motionEveryNSteps = 10;  // motion.csv rows and .glb keyframes every n steps (and the first and last)
    int objEveryNSteps = 10;     // one OBJ frame every n steps (and the first and last); 0 = none
    int pngEveryNSteps = 10;     // one PNG frame every n steps (and the first and last); 0 = none
    RenderSettings image;        // PNG frames
};

// What a run produces (scene key effects.outputs).
struct SceneOutputFormats {
    bool motion = true;  // meshes/<body>.obj once (body frame, crack faces "interior") + motion.csv
    bool gltf = true;    // scene.glb: the bodies' meshes and their motion as a glTF 2.0 animation
    bool obj = false;    // per-frame OBJ, one object per body (world frame)
    bool vdb = false;    // fractured level sets (needs fracture)
    bool csv = false;    // statistics.csv (one row per fracture event) and the fragment-volume histogram
    bool png = false;    // preview frames, contact sheet, charts
};

struct SceneEffects {
    SceneOutputFormats outputs;
    // Run seed, combined with every body's noise seed; --seed overrides it. Runs with the same
    // seed give the same output.
    std::uint64_t seed = 0;
    // What a fracture event cuts into the level set (BemFractureEngineSettings::voxelFronts):
    // "markers" (the surface swept by the voxel-resolution fronts, default) or "coarse_sheet".
    bool voxelFronts = true;
    // BEM and crack matrices idle bodies may keep [MB] (BemFractureEngineSettings::idleMatrixBudgetMB).
    double idleMatrixBudgetMB = BemFractureEngineSettings().idleMatrixBudgetMB;
    // FULL seeds surface-breaking cracks (CrackSettings::surfaceSeeds).
    bool surfaceSeeds = BemFractureEngineSettings().fracture.surfaceSeeds;
    // EST's fronts end on the surface (CrackSettings::estimatorSurfaceFronts).
    bool estimatorSurfaceFronts = BemFractureEngineSettings().fracture.estimatorSurfaceFronts;
    // Fragments sleep by their size in islands of touching bodies
    // (btFractureDynamicsWorld::setFragmentSleeping); off: Bullet's thresholds and islands.
    bool fragmentSleeping = false;
};

// Settings of one run that do not belong to the scene file (command line).
struct SceneRunSettings {
    int threads = 0;  // worker threads for OpenMP and TBB; 0 = the libraries' default
};

struct Scene {
    std::string file;  // the scene file, as given
    std::string name;  // its stem ("column_bunny")
    SceneWorldSettings world;
    std::vector<SceneBody> bodies;
    SceneOutputs outputs;
    SceneEffects effects;
    SceneRunSettings run;
};

// Sets the method of every breakable body (the runner's --method).
void overrideFractureMethod(Scene& scene, FractureMethod method);

// Reads and validates a scene file; mesh paths are resolved against its folder and must exist.
Scene readSceneFile(const std::string& path);

// The same for JSON text already in memory: `source` names it in messages, `baseDirectory`
// resolves relative mesh paths.
Scene parseScene(const std::string& jsonText, const std::string& source, const std::string& baseDirectory);

}  // namespace btfracture
