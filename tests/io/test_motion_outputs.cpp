// SPDX-License-Identifier: Zlib
// The default outputs: crack faces found on a cut box, body meshes with their materials, the
// glTF binary's structure and keys, and motion.csv and the meshes of a run of a scene world.
#include <btFracture/core/Error.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/io/CrackFaces.h>
#include <btFracture/io/GltfWriter.h>
#include <btFracture/io/MotionRecorder.h>
#include <btFracture/io/ObjReader.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/SceneWorld.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "btfracture_test_motion_outputs";
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// The right half (x > 0) of the box [-1, 1]^3, in its own frame (centred at x = 0.5).
TriangleMesh rightHalf() {
    return makeBox(Eigen::Vector3d(0.5, 1.0, 1.0));
}
Eigen::Isometry3d boxFromHalf() {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(0.5, 0.0, 0.0);
    return t;
}

}  // namespace

TEST(CrackFaces, TheCutFaceOfAHalvedBoxIsInterior) {
    const ClosestPointTree box(makeBox(Eigen::Vector3d::Ones()));
    const TriangleMesh half = rightHalf();
    const std::vector<bool> crack = crackFaces(half, boxFromHalf(), box, 0.01);
    ASSERT_EQ(crack.size(), half.triangles.size());
    int interior = 0;
    for (size_t t = 0; t < crack.size(); ++t) {
        const auto& tri = half.triangles[t];
        const bool onCut = half.vertices[tri[0]].x() < 0.0 && half.vertices[tri[1]].x() < 0.0 &&
                           half.vertices[tri[2]].x() < 0.0;  // the face at x = -0.5 (the box's x = 0)
        EXPECT_EQ(crack[t], onCut) << "triangle " << t;
        interior += crack[t] ? 1 : 0;
    }
    EXPECT_EQ(interior, 2);
    // A fragment displaced by more than the tolerance matches nothing: all cut.
    Eigen::Isometry3d away = boxFromHalf();
    away.translation().y() += 0.05;
    const std::vector<bool> moved = crackFaces(half, away, box, 0.01);
    // The +-y faces left the original's surface, the x and z faces slid within its planes.
    EXPECT_EQ(std::count(moved.begin(), moved.end(), true), 6);
}

TEST(ObjWriter, GroupsFacesByMaterial) {
    const TriangleMesh half = rightHalf();
    std::vector<bool> crack(half.triangles.size(), false);
    crack[3] = crack[7] = true;
    const auto path = scratch("half.obj");
    {
        ObjWriter writer(path.string());
        writer.addObject("half", half, crack, "materials.mtl");
        writer.close();
    }
    const std::vector<std::string> text = lines(readText(path));
    ASSERT_GE(text.size(), 3u);
    EXPECT_EQ(text[0], "mtllib materials.mtl");
    EXPECT_EQ(text[1], "o half");
    int outside = -1, interior = -1, faces = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == "usemtl outside") outside = static_cast<int>(i);
        if (text[i] == "usemtl interior") interior = static_cast<int>(i);
        faces += text[i].rfind("f ", 0) == 0 ? 1 : 0;
    }
    ASSERT_GT(outside, 0);
    EXPECT_EQ(interior, outside + 1 + 10);  // ten outside faces, then the two crack faces
    EXPECT_EQ(faces, 12);
    EXPECT_EQ(readObj(path.string()).triangles.size(), 12u);  // readers skip the materials

    writeObjMaterials(scratch("materials.mtl").string());
    const std::string library = readText(scratch("materials.mtl"));
    EXPECT_NE(library.find("newmtl outside\nKd "), std::string::npos);
    EXPECT_NE(library.find("newmtl interior\nKd "), std::string::npos);
    ObjWriter mismatch(scratch("bad.obj").string());
    EXPECT_THROW(mismatch.addObject("half", half, std::vector<bool>(3, true), "materials.mtl"), Error);
}

namespace {

struct Glb {
    nlohmann::json json;
    std::vector<char> bin;
    std::uint32_t magic = 0, version = 0, length = 0;
    size_t fileSize = 0;

    // Floats of accessor `index` (tightly packed, as the writer lays them out).
    std::vector<float> floats(int index) const {
        const auto& accessor = json["accessors"][index];
        const auto& view = json["bufferViews"][accessor["bufferView"].get<int>()];
        std::vector<float> out(view["byteLength"].get<size_t>() / sizeof(float));
        std::memcpy(out.data(), bin.data() + view["byteOffset"].get<size_t>(), out.size() * sizeof(float));
        return out;
    }
};

Glb readGlb(const std::filesystem::path& path) {
    const std::string bytes = readText(path);
    Glb glb;
    glb.fileSize = bytes.size();
    const auto word = [&](size_t at) {
        std::uint32_t w = 0;
        std::memcpy(&w, bytes.data() + at, 4);
        return w;
    };
    glb.magic = word(0);
    glb.version = word(4);
    glb.length = word(8);
    const std::uint32_t jsonLength = word(12);
    EXPECT_EQ(word(16), 0x4E4F534Au);
    EXPECT_EQ(jsonLength % 4, 0u);
    glb.json = nlohmann::json::parse(bytes.substr(20, jsonLength));
    const size_t binAt = 20 + jsonLength;
    const std::uint32_t binLength = word(binAt);
    EXPECT_EQ(word(binAt + 4), 0x004E4942u);
    glb.bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(binAt + 8),
                   bytes.begin() + static_cast<std::ptrdiff_t>(binAt + 8 + binLength));
    return glb;
}

}  // namespace

TEST(GltfWriter, NodesMeshesMaterialsAndKeys) {
    const std::vector<double> times{0.0, 0.1, 0.2, 0.3};
    GltfBody still;
    still.name = "ground";
    still.surface = makeBox(Eigen::Vector3d(2.0, 0.1, 2.0));
    still.positions.assign(4, Eigen::Vector3d(0.0, -0.1, 0.0));
    still.orientations.assign(4, Eigen::Quaterniond::Identity());
    GltfBody piece;
    piece.name = "box_f1";
    piece.surface = rightHalf();
    piece.crackFaces.assign(piece.surface.triangles.size(), false);
    piece.crackFaces[0] = true;
    piece.firstSample = 1;
    piece.positions = {{0.0, 1.0, 0.0}, {0.0, 0.9, 0.0}};
    piece.orientations = {Eigen::Quaterniond::Identity(),
                          Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))};
    piece.removed = true;  // hidden from sample 3 on
    const auto path = scratch("scene.glb");
    writeGlb(path.string(), times, {still, piece});

    const Glb glb = readGlb(path);
    EXPECT_EQ(glb.magic, 0x46546C67u);
    EXPECT_EQ(glb.version, 2u);
    EXPECT_EQ(glb.length, glb.fileSize);
    const auto& json = glb.json;
    EXPECT_EQ(json["asset"]["version"], "2.0");
    ASSERT_EQ(json["nodes"].size(), 2u);
    EXPECT_EQ(json["nodes"][1]["name"], "box_f1");
    EXPECT_EQ(json["nodes"][1]["scale"], nlohmann::json({0.0, 0.0, 0.0}));  // not there at t = 0
    EXPECT_EQ(json["materials"][0]["name"], "outside");
    EXPECT_EQ(json["materials"][1]["name"], "interior");
    EXPECT_EQ(json["meshes"][0]["primitives"].size(), 1u);  // the ground: outside only
    const auto& primitives = json["meshes"][1]["primitives"];
    ASSERT_EQ(primitives.size(), 2u);
    EXPECT_EQ(primitives[1]["material"], 1);
    EXPECT_EQ(json["accessors"][primitives[1]["indices"].get<int>()]["count"], 3);  // one crack triangle

    // The ground never moves: no keys. The piece: translation, rotation, and scale keys.
    const auto& animation = json["animations"][0];
    std::map<std::string, int> samplerOf;
    for (const auto& channel : animation["channels"]) {
        EXPECT_EQ(channel["target"]["node"], 1);
        samplerOf[channel["target"]["path"].get<std::string>()] = channel["sampler"].get<int>();
    }
    ASSERT_EQ(samplerOf.size(), 3u);
    const auto& translation = animation["samplers"][samplerOf["translation"]];
    EXPECT_EQ(glb.floats(translation["input"].get<int>()), (std::vector<float>{0.1f, 0.2f}));
    EXPECT_EQ(glb.floats(translation["output"].get<int>()),
              (std::vector<float>{0.0f, 1.0f, 0.0f, 0.0f, 0.9f, 0.0f}));
    const auto& rotation = animation["samplers"][samplerOf["rotation"]];
    const std::vector<float> q = glb.floats(rotation["output"].get<int>());
    ASSERT_EQ(q.size(), 8u);
    EXPECT_NEAR(q[6], std::sin(0.15), 1e-6);  // z of the second key (x, y, z, w)
    const auto& scale = animation["samplers"][samplerOf["scale"]];
    EXPECT_EQ(scale["interpolation"], "STEP");
    EXPECT_EQ(glb.floats(scale["input"].get<int>()), (std::vector<float>{0.0f, 0.1f, 0.3f}));
    EXPECT_EQ(glb.floats(scale["output"].get<int>()), (std::vector<float>{0, 0, 0, 1, 1, 1, 0, 0, 0}));
    // Accessor bounds are the data's.
    const auto& output = json["accessors"][translation["output"].get<int>()];
    EXPECT_EQ(output["min"], nlohmann::json({0.0f, 0.9f, 0.0f}));
    EXPECT_EQ(output["max"], nlohmann::json({0.0f, 1.0f, 0.0f}));

    EXPECT_THROW(writeGlb(path.string(), {0.0, 0.0}, {still}), Error);  // times must increase
    piece.firstSample = 3;                                              // samples beyond the times
    EXPECT_THROW(writeGlb(path.string(), times, {piece}), Error);
}

TEST(MotionRecorder, MeshesOnceAndOneRowPerBodyAndSample) {
    SceneWorld world(parseScene(R"({"world": {"dt": 0.01},
        "bodies": [{"name": "ground", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
                   {"name": "box", "shape": {"type": "box", "half_extents": [0.5, 0.5, 0.5]},
                    "position": [0, 2, 0], "linear_velocity": [1, 0, 0]}]})",
                                "test.json", "."));
    const auto dir = scratch("run");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    MotionRecorder recorder(dir.string(), true, (dir / "scene.glb").string());
    for (int frame = 0; frame < 3; ++frame) {
        if (frame > 0) world.stepFrame();
        recorder.sample(world);
    }
    recorder.close();
    EXPECT_EQ(recorder.samples(), 3);
    EXPECT_EQ(recorder.bodies(), 2);
    const std::vector<std::string> rows = lines(readText(dir / "motion.csv"));
    ASSERT_EQ(rows.size(), 1u + 3u * 2u);
    EXPECT_EQ(rows[0], "frame,time_s,name,parent,px,py,pz,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz,alive");
    EXPECT_EQ(rows[2], "0,0,box,,0,2,0,0,0,0,1,1,0,0,0,0,0,1");
    EXPECT_EQ(rows[6].substr(0, 11), "2,0.02,box,");
    EXPECT_TRUE(std::filesystem::exists(dir / "meshes" / "box.obj"));
    EXPECT_TRUE(std::filesystem::exists(dir / "meshes" / "ground.obj"));
    EXPECT_TRUE(std::filesystem::exists(dir / "meshes" / "materials.mtl"));
    const Glb glb = readGlb(dir / "scene.glb");
    EXPECT_EQ(glb.json["nodes"].size(), 2u);
    EXPECT_EQ(glb.json["animations"][0]["channels"].size(), 2u);  // the box moves, the ground does not
}
