// SPDX-License-Identifier: Zlib
// demos/scenes/scene.schema.json against the scene parser (io/SceneFile): every shipped scene
// validates, scenes the parser rejects for a key or a range are rejected by the schema too, and
// at every object the parser's set of accepted keys is exactly the schema's.
#include "JsonSchema.h"

#include <btFracture/core/Error.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/SceneFile.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace btfracture {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kScenes = std::string(BTFRACTURE_MESH_DIR) + "/../scenes";

test::JsonSchema sceneSchema() {
    return test::JsonSchema(Json::parse(readWholeFile(kScenes + "/scene.schema.json", "schema")));
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += "\n  " + line;
    return text;
}

std::vector<fs::path> jsonFiles(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SceneSchema, EveryShippedSceneValidatesAndNamesTheSchema) {
    const test::JsonSchema schema = sceneSchema();
    const std::vector<fs::path> scenes = jsonFiles(kScenes);
    ASSERT_GE(scenes.size(), 9u);
    for (const fs::path& file : scenes) {
        const Json scene = Json::parse(readWholeFile(file.string(), "scene"));
        EXPECT_EQ(scene.value("$schema", ""), "scene.schema.json") << file;  // editors find the schema
        const std::vector<std::string> problems = schema.validate(scene);
        EXPECT_TRUE(problems.empty())
            << file << joined(problems);  // the parser: SceneFile.ShippedScenesParse
    }
}

// The benchmarks' scenes (bench/scenes) are scene files as users write them: they parse and
// validate too, so that a change of the format cannot break `make bench` unnoticed.
TEST(SceneSchema, BenchmarkScenesParseAndValidate) {
    const test::JsonSchema schema = sceneSchema();
    const std::vector<fs::path> scenes = jsonFiles(std::string(BTFRACTURE_MESH_DIR) + "/../../bench/scenes");
    ASSERT_GE(scenes.size(), 1u);
    for (const fs::path& file : scenes) {
        const Json scene = Json::parse(readWholeFile(file.string(), "scene"));
        EXPECT_EQ(scene.value("$schema", ""), "../../demos/scenes/scene.schema.json") << file;
        const std::vector<std::string> problems = schema.validate(scene);
        EXPECT_TRUE(problems.empty()) << file << joined(problems);
        EXPECT_NO_THROW(readSceneFile(file.string())) << file;
    }
}

// Scenes that exercise every key: the schema accepts what the parser accepts.
TEST(SceneSchema, EveryFeatureSceneValidates) {
    const test::JsonSchema schema = sceneSchema();
    const fs::path corpus = fs::path(BTFRACTURE_TEST_DATA_DIR) / "../../fuzz/corpus/scene_parser";
    for (const char* name : {"every_feature.json", "box_on_plane.json", "column_bunny.json"}) {
        const fs::path file = corpus / name;
        const Json scene = Json::parse(readWholeFile(file.string(), "scene"));
        EXPECT_TRUE(schema.validate(scene).empty()) << file << joined(schema.validate(scene));
    }
}

TEST(SceneSchema, RejectsWhatTheParserRejectsForKeysAndRanges) {
    const test::JsonSchema schema = sceneSchema();
    const fs::path bad = fs::path(BTFRACTURE_TEST_DATA_DIR) / "scenes";
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"unknown_key.json", "bodies[1].velocty: unknown key"},
        {"bad_material.json", "bodies[1].material.nu: expected < 0.5, got 0.7"},
    };
    for (const auto& [name, expected] : cases) {
        const Json scene = Json::parse(readWholeFile((bad / name).string(), "scene"));
        const std::string problems = joined(schema.validate(scene));
        EXPECT_NE(problems.find(expected), std::string::npos) << name << problems;
        EXPECT_THROW(readSceneFile((bad / name).string()), Error) << name;
    }
    const std::vector<std::pair<std::string, std::string>> inline_cases = {
        {R"({"bodies": []})", "bodies: expected at least 1 items"},
        {R"({"bodies": [{"shape": {"type": "cone"}}]})", "bodies[0].shape: matches none of the oneOf"},
        {R"({"bodies": [{"shape": {"type": "sphere", "radius": 1}, "state": "frozen"}]})", "bodies[0].state"},
        {R"({"world": {"steps": 2.5}, "bodies": [{"shape": {"type": "sphere", "radius": 1}}]})",
         "world.steps"},
        {R"({"bodies": [{"shape": {"type": "sphere", "radius": 1}, "material": {"E": 1e9}}]})",
         "bodies[0].material: matches none of the oneOf"},
        {R"({"bodies": [{"shape": {"type": "sphere", "radius": 1}}], "effects": {"outputs": ["obj", "obj"]}})",
         "effects.outputs: item \"obj\" is listed twice"},
    };
    for (const auto& [text, expected] : inline_cases) {
        const std::string problems = joined(schema.validate(Json::parse(text)));
        EXPECT_NE(problems.find(expected), std::string::npos) << text << problems;
        EXPECT_THROW(parseScene(text, "inline.json", "."), Error) << text;
    }
}

// The keys the parser accepts at a path, read off its "unknown key (expected one of: ...)" error.
std::set<std::string> parserKeys(const std::string& sceneText) {
    try {
        parseScene(sceneText, "probe.json", kScenes);
    } catch (const Error& e) {
        const std::string message = e.what();
        const std::string marker = "unknown key (expected one of: ";
        const size_t at = message.find(marker);
        if (at == std::string::npos) throw std::runtime_error("unexpected parser error: " + message);
        std::istringstream list(message.substr(at + marker.size(), message.rfind(')') - at - marker.size()));
        std::set<std::string> keys;
        for (std::string key; std::getline(list, key, ',');)
            keys.insert(key.substr(key.find_first_not_of(' ')));
        return keys;
    }
    throw std::runtime_error("the parser accepted the probe key in " + sceneText);
}

std::set<std::string> propertyNames(const Json& schemaNode) {
    std::set<std::string> names;
    for (const auto& item : schemaNode.at("properties").items()) names.insert(item.key());
    return names;
}

TEST(SceneSchema, AcceptsExactlyTheParsersKeysAtEveryObject) {
    const test::JsonSchema schema = sceneSchema();
    const auto scene = [&](const std::string& bodyExtra, const std::string& rest) {
        return R"({"bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.1})" + bodyExtra +
               "}]" + rest + "}";
    };
    // Each probe puts the unknown key "zz" into one object; the schema definitions it belongs to.
    struct Probe {
        std::string text;
        std::vector<std::string> definitions;  // "" = the root
    };
    const std::vector<Probe> probes = {
        {scene("", R"(, "zz": 1)"), {""}},
        {scene("", R"(, "world": {"zz": 1})"), {"world"}},
        {scene(R"(, "zz": 1)", ""), {"body"}},
        {R"({"bodies": [{"shape": {"type": "mesh", "file": "../meshes/bunny.obj", "zz": 1}}]})",
         {"meshShape"}},
        {R"({"bodies": [{"shape": {"type": "box", "half_extents": [1, 1, 1], "zz": 1}}]})", {"boxShape"}},
        {R"({"bodies": [{"shape": {"type": "sphere", "radius": 1, "zz": 1}}]})", {"sphereShape"}},
        {R"({"bodies": [{"shape": {"type": "plane", "zz": 1}}]})", {"planeShape"}},
        {scene(R"(, "orientation": {"zz": 1})", ""), {"axisAngle", "quaternion"}},
        {scene(R"(, "material": {"zz": 1})", ""), {"materialValues"}},
        {scene(R"(, "resolution": {"zz": 1})", ""), {"resolution"}},
        {scene("", R"(, "outputs": {"zz": 1})"), {"outputs"}},
        {scene("", R"(, "outputs": {"image": {"zz": 1}})"), {"image"}},
        {scene("", R"(, "effects": {"zz": 1})"), {"effects"}},
        {scene("", R"(, "effects": {"fracture": {"ball": {"zz": 1}}})"), {"bodyFracture"}},
        {scene("", R"(, "effects": {"fracture": {"ball": {"material_noise": {"amplitude": 0, "zz": 1}}}})"),
         {"materialNoise"}},
    };
    std::set<std::string> covered;
    for (const Probe& probe : probes) {
        std::set<std::string> schemaKeys;
        for (const std::string& name : probe.definitions) {
            const std::set<std::string> own =
                propertyNames(name.empty() ? schema.root() : schema.definition(name));
            schemaKeys.insert(own.begin(), own.end());
            covered.insert(name);
        }
        EXPECT_EQ(parserKeys(probe.text), schemaKeys) << probe.text;
    }
    // Every object of the schema is probed: a new object in either needs a probe here.
    std::set<std::string> objects = {""};
    for (const auto& item : schema.root().at("$defs").items())
        if (item.value().contains("properties")) objects.insert(item.key());
    EXPECT_EQ(covered, objects);
}

}  // namespace
}  // namespace btfracture
