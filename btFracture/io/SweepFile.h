// SPDX-License-Identifier: Zlib
#pragma once
// Sweep files: many runs of one base scene, each with its own impact (btfracture-sweep). The
// format is in demos/README.md ("Sweeps") and demos/sweep/sweep.schema.json: the base scene, the
// target body and the impactor, the number of runs, a sweep seed and the distributions of the
// varied quantities (impactor speed, direction, impact point on the target's surface, impactor
// size and mass, target orientation, material-noise seed, fracture method).
//
// Run i is a pure function of (sweep file, i): every quantity draws from its own stream of a
// counter-based generator keyed by (sweep seed, i, quantity), so that no run depends on another,
// on the order runs are done in, or on how the sweep is split into shards. Trigonometry goes
// through core/PortableMath.h, so the drawn values are the same on every CPU.
#include <btFracture/core/FractureSettings.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/io/SceneFile.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace btfracture {

// A number drawn per run: a constant, uniform on [low, high], or one of a list.
struct SweepNumber {
    enum class Kind { Constant, Uniform, Choice } kind = Kind::Constant;
    std::vector<double> values;  // Constant: {c}; Uniform: {low, high}; Choice: the list
};

enum class SweepOrientation { Fixed, AboutUp, Uniform };

struct SweepSpec {
    std::string file;       // the sweep file, as given
    std::string sceneFile;  // the base scene (resolved against the sweep file's folder)
    std::string target;     // the body that is hit
    std::string impactor;   // the body that hits it (a sphere or a box)
    int runs = 0;
    std::uint64_t seed = 0;           // sweep seed
    std::optional<int> steps;         // replaces the scene's world.steps
    std::optional<int> bemTriangles;  // replaces the target's resolution.bem_triangles

    SweepNumber speed;                                 // [m/s]
    SweepNumber coneHalfAngleDegrees;                  // direction within this angle of the inward normal
    Eigen::Vector3d facing = Eigen::Vector3d::Zero();  // impact points whose world normal . facing
    double minFacingCosine = -1.0;                     // is at least this (facing zero: any point)
    double standoff = 0.02;                            // [m] gap between impactor and target at the start
    SweepNumber impactorScale;                         // times the impactor's size
    std::optional<SweepNumber> impactorMass;           // [kg]; none: the scene's mass or density
    SweepOrientation orientation = SweepOrientation::Fixed;
    bool noiseSeedPerRun = false;         // effects.seed drawn per run (else the scene's)
    std::vector<FractureMethod> methods;  // one drawn per run; empty: the scene's
};

// Reads and validates a sweep file and its base scene. Throws btfracture::Error
// "<file>: <key>: <what was expected>" like the scene reader.
SweepSpec readSweepFile(const std::string& path);

// What run `index` of a sweep does, in the target's rest frame (its mesh frame with the scene's
// scale: the scene's position and orientation undone) and in the world.
struct SweepRunParameters {
    int index = 0;
    double speed = 0.0;                     // [m/s]
    Eigen::Vector3d pointRest, normalRest;  // impact point and outward normal, rest frame
    Eigen::Vector3d pointWorld, direction;  // impact point and the impactor's unit velocity, world
    double impactorScale = 1.0;
    std::optional<double> impactorMass;                                     // [kg]
    Eigen::Quaterniond targetOrientation = Eigen::Quaterniond::Identity();  // world
    std::uint64_t seed = 0;                                                 // effects.seed of the run
    FractureMethod method = FractureMethod::Full;
};

// The runs [first, last) of shard k of K (0 <= k < K): contiguous, as even as possible, together
// every run exactly once. Throws btfracture::Error for k or K out of range.
std::pair<int, int> shardRuns(int runs, int k, int shards);

class SweepRunBuilder {
public:
    // Reads the base scene and the target's surface once.
    explicit SweepRunBuilder(const SweepSpec& spec);
    const Scene& baseScene() const { return base_; }
    // Run `index`'s parameters, and its scene with them applied. Throws btfracture::Error when
    // no impact point satisfies the facing condition.
    SweepRunParameters parameters(int index) const;
    Scene scene(const SweepRunParameters& run) const;
    // The target's pose in the run's world: maps rest-frame points to world points.
    Eigen::Isometry3d targetRestToWorld(const SweepRunParameters& run) const;

private:
    SweepSpec spec_;
    Scene base_;
    size_t targetIndex_ = 0, impactorIndex_ = 0;
    TriangleMesh restSurface_;            // the target's surface, rest frame
    std::vector<double> cumulativeArea_;  // over its triangles
};

}  // namespace btfracture
