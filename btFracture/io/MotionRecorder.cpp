// SPDX-License-Identifier: Zlib
#include <btFracture/io/MotionRecorder.h>

#include <btFracture/core/Error.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/SceneWorld.h>
#include <btFracture/io/StatisticsCsv.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace btfracture {
namespace {

constexpr const char* kMaterialLibrary = "materials.mtl";

Eigen::Vector3d toEigen(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}

}  // namespace

MotionRecorder::MotionRecorder(const std::string& directory, bool meshesAndCsv, std::string glbPath)
    : glbPath_(std::move(glbPath)) {
    if (!meshesAndCsv) return;
    meshDirectory_ = (std::filesystem::path(directory) / "meshes").string();
    std::error_code error;
    std::filesystem::create_directories(meshDirectory_, error);
    if (error) throw Error("cannot create mesh folder '" + meshDirectory_ + "': " + error.message());
    writeObjMaterials((std::filesystem::path(meshDirectory_) / kMaterialLibrary).string());
    const std::string csvPath = (std::filesystem::path(directory) / "motion.csv").string();
    csv_.open(csvPath, std::ios::binary | std::ios::trunc);
    if (!csv_) throw Error("cannot create '" + csvPath + "': " + std::strerror(errno));
    csv_ << "frame,time_s,name,parent,px,py,pz,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz,alive\n";
}

void MotionRecorder::sample(const SceneWorld& world) {
    if (closed_) throw Error("MotionRecorder: sample after close");
    const int frame = static_cast<int>(times_.size());
    const double time = world.time();
    times_.push_back(time);
    const auto row = [&](const std::string& name, const std::string& parent, const btTransform& pose,
                         const btVector3& v, const btVector3& w, int alive) {
        if (!csv_.is_open()) return;
        const btVector3& p = pose.getOrigin();
        const btQuaternion q = pose.getRotation();
        char numbers[512];
        std::snprintf(numbers, sizeof numbers,
                      "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d\n",
                      static_cast<double>(p.x()), static_cast<double>(p.y()), static_cast<double>(p.z()),
                      static_cast<double>(q.x()), static_cast<double>(q.y()), static_cast<double>(q.z()),
                      static_cast<double>(q.w()), static_cast<double>(v.x()), static_cast<double>(v.y()),
                      static_cast<double>(v.z()), static_cast<double>(w.x()), static_cast<double>(w.y()),
                      static_cast<double>(w.z()), alive);
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.9g", time);
        csv_ << frame << ',' << seconds << ',' << csvField(name) << ',' << csvField(parent) << ',' << numbers;
    };

    const std::vector<SceneWorld::Removal>& removals = world.removals();
    for (; removalsSeen_ < removals.size(); ++removalsSeen_) {
        const SceneWorld::Removal& removal = removals[removalsSeen_];
        const auto found = index_.find(removal.name);
        if (found == index_.end()) continue;  // came and went between two samples
        GltfBody& body = bodies_[found->second];
        body.removed = true;
        row(removal.name, parentOf_[found->second], removal.pose, removal.linearVelocity,
            removal.angularVelocity, 0);
    }
    for (const SceneWorld::Body& b : world.bodies()) {
        auto found = index_.find(b.name);
        if (found == index_.end()) {
            GltfBody body;
            body.name = b.name;
            body.surface = b.surface;
            body.crackFaces = b.crackFaces;
            body.firstSample = frame;
            if (!meshDirectory_.empty()) {
                ObjWriter writer((std::filesystem::path(meshDirectory_) / (b.name + ".obj")).string());
                writer.addObject(b.name, b.surface, b.crackFaces, kMaterialLibrary);
                writer.close();
            }
            found = index_.emplace(b.name, bodies_.size()).first;
            bodies_.push_back(std::move(body));
            parentOf_.push_back(b.parent);
        }
        GltfBody& body = bodies_[found->second];
        const btTransform& pose = b.rigidBody->getWorldTransform();
        const btQuaternion q = pose.getRotation();
        body.positions.push_back(toEigen(pose.getOrigin()));
        body.orientations.emplace_back(q.w(), q.x(), q.y(), q.z());
        row(b.name, b.parent, pose, b.rigidBody->getLinearVelocity(), b.rigidBody->getAngularVelocity(), 1);
    }
}

void MotionRecorder::close() {
    if (closed_) return;
    closed_ = true;
    if (csv_.is_open()) {
        csv_.close();
        if (csv_.fail()) throw Error("writing motion.csv in '" + meshDirectory_ + "/..' failed");
    }
    if (!glbPath_.empty() && !times_.empty()) writeGlb(glbPath_, times_, bodies_);
}

}  // namespace btfracture
