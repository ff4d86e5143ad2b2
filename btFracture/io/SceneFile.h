#pragma once
// Scene files for the headless runner: JSON parsed and validated into a plain Scene (SI units).
// The format is documented with examples in demos/README.md. Every problem is a
// btfracture::Error "<file>: <key path>: <what was expected>", e.g.
//   column_bunny.json: bodies[2].shape.radius: expected a positive number [m], got -0.2
// Unknown keys are errors too, so that a typo never silently falls back to a default.
#include <btFracture/core/Material.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

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
    SceneMeshCollision collision = SceneMeshCollision::ConvexHull;  // Mesh
    Eigen::Vector3d halfExtents{0.5, 0.5, 0.5};                     // Box [m], before scale
    double radius = 0.5;                                            // Sphere [m], before scale
    Eigen::Vector3d normal{0.0, 1.0, 0.0};                          // Plane: unit normal, world frame
    double offset = 0.0;  // Plane: points x with normal . x = offset [m]
};

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
    bool fracturable = false;  // stored for the fracture issues; the rigid runner ignores it

    bool isStatic() const { return shape.type == SceneShapeType::Plane || (mass && *mass == 0.0); }
};

struct SceneOutputs {
    std::string
        directory;  // empty: the runner's choice (out/<scene name>); relative to the working directory
    int objEveryNSteps = 10;  // one OBJ frame every n steps (and the first and last); 0 = none
};

struct Scene {
    std::string file;  // the scene file, as given
    std::string name;  // its stem ("column_bunny")
    SceneWorldSettings world;
    std::vector<SceneBody> bodies;
    SceneOutputs outputs;
};

// Reads and validates a scene file; mesh paths are resolved against its folder and must exist.
Scene readSceneFile(const std::string& path);

// The same for JSON text already in memory: `source` names it in messages, `baseDirectory`
// resolves relative mesh paths.
Scene parseScene(const std::string& jsonText, const std::string& source, const std::string& baseDirectory);

}  // namespace btfracture
