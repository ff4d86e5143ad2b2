// SPDX-License-Identifier: Zlib
#pragma once
// The default outputs of a run: every body's mesh once, and its motion.
//   meshes/<body>.obj   the body's surface in its own frame (centre of mass, principal axes),
//                       written when the body first appears; faces under "usemtl outside" or
//                       "usemtl interior" (crack faces), materials in meshes/materials.mtl
//   motion.csv          one row per body and sample: frame,time_s,name,parent,
//                       px,py,pz,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz,alive; world pose (body frame ->
//                       world: position [m], unit quaternion) and velocities [m/s, rad/s]. A body
//                       that broke has one last row with alive 0 (its state when it broke) at
//                       the first sample it is missing from.
//   scene.glb           the same as a glTF 2.0 animation (io/GltfWriter.h), written by close().
// A body that broke and left again between two samples appears in none of them.
#include <btFracture/io/GltfWriter.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace btfracture {

class SceneWorld;

class MotionRecorder {
public:
    // `directory` receives meshes/ and motion.csv when `meshesAndCsv`; `glbPath` the .glb when
    // non-empty. Throws btfracture::Error naming a file that cannot be created.
    MotionRecorder(const std::string& directory, bool meshesAndCsv, std::string glbPath);

    // One sample of every body in `world` at world.time().
    void sample(const SceneWorld& world);
    // Writes the .glb and closes motion.csv (throws Error naming the file when writing failed).
    void close();

    int samples() const { return static_cast<int>(times_.size()); }
    int bodies() const { return static_cast<int>(bodies_.size()); }

private:
    std::string meshDirectory_, glbPath_;
    std::ofstream csv_;
    std::vector<double> times_;
    std::vector<GltfBody> bodies_;
    std::vector<std::string> parentOf_;    // per bodies_ entry
    std::map<std::string, size_t> index_;  // body name -> bodies_
    size_t removalsSeen_ = 0;
    bool closed_ = false;
};

}  // namespace btfracture
