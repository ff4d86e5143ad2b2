// SPDX-License-Identifier: Zlib
#pragma once
// FractureRB compatibility: the scene format of Hahn & Wojtan's FractureRB (a Bullet world file
// plus a per-object parameter CSV), read into the same Scene the JSON path produces, so that
// existing data-set pipelines can switch to btFracture.
//
// The CSV (columns numbered from 1 here; FractureRB's own comments count from 0):
//   ';'-separated fields, surrounding blanks trimmed; a line starting with '%' is a comment and a
//   field starting with '%' comments out the rest of its line; empty lines are skipped.
//    1  object name in the .bullet file          13  Poisson ratio nu
//    2  new name (used in outputs)               14  density [kg/m^3]
//    3-5  linear velocity [m/s]                  15  tensile strength [Pa]
//    6-8  angular velocity [rad/s]               16  fracture toughness [Pa m^1/2]
//    9  state: 0 dynamic, 1 sleeping, 2 kinematic 17 compressive factor
//   10  crack mesh size h [m]                    18  remesh target [triangles] (> 3: remesh)
//   11  voxel size [m]                           19  ignore crack self-intersection (> 0)
//   12  Young's modulus E [Pa]                   20  material model ("default" = homogeneous)
//   21  max cracks per event (-1 = any), optional   22  method, optional (0 full, 1 est)
//   23  crack-front sampling density, optional
// A row has 2 columns (rename), 9 (plus velocities and state) or 20 to 23 (a breakable body).
#include <btFracture/core/Material.h>
#include <btFracture/io/SceneFile.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace btfracture {

struct FractureRbObject {
    std::string key;                                                 // column 1
    int line = 0;                                                    // where the row is, for messages
    std::string name;                                                // column 2
    std::optional<Eigen::Vector3d> linearVelocity, angularVelocity;  // columns 3-8
    SceneMotion motion = SceneMotion::Dynamic;                       // column 9
    struct Breakable {
        double crackMeshSize = 0.0;  // h [m]
        double voxelSize = 0.0;      // [m]
        Material material = Material::steel();
        int remeshTarget = 0;  // > 3: the BEM mesh is remeshed to this many triangles
        bool ignoreCrackSelfIntersection = false;
        std::string materialModel = "default";
        int maxCracks = -1;
        FractureMethod method = FractureMethod::Full;
        double samplingDensity = 1.0;
    };
    std::optional<Breakable> breakable;  // columns 10-23
};

// Parses the CSV text; `source` names it in messages. Throws btfracture::Error
// "<source>:<line>: column <c> (<field>): <what was expected>, got '<text>'" for malformed rows,
// wrong column counts, out-of-range values and keys given twice.
std::vector<FractureRbObject> parseFractureRbCsv(const std::string& text, const std::string& source);

// Reads the Bullet world file (btBulletWorldImporter) and the CSV into a Scene:
//  - every rigid body and collision object of the file becomes a body, named as in the file (or
//    by column 2), with its pose, mass (0: static; kinematic flag kept), friction, restitution
//    and velocities; boxes, spheres, static planes, convex hulls and triangle meshes (BVH,
//    scaled BVH, GImpact, convex triangle mesh: read from their mesh data, so that Debian's
//    importer not restoring GImpact bodies does not matter) and compounds with one child;
//  - a CSV row sets velocities and state, and with 20 or more columns makes a dynamic body
//    breakable: its material, voxel size, crack element size (the crack mesh size), BEM
//    resolution (the remesh target, else the mesh's own triangle count, as FractureRB does),
//    fracture method, and a mass from density x volume (as FractureRB recomputes it); settings
//    btFracture has no use for are logged;
//  - the world: the file's gravity, dt = 1/250 s and 1000 steps (FractureRB's defaults),
//    outputs motion, gltf, csv and png.
// Throws btfracture::Error naming the file (and for CSV problems line and column) when a file
// cannot be read, a shape is not supported or a CSV row names no object of the file.
Scene readFractureRbScene(const std::string& bulletFile, const std::string& csvFile);

}  // namespace btfracture
