// SPDX-License-Identifier: Zlib
#include <btFracture/io/GltfWriter.h>

#include <btFracture/core/Error.h>
#include <btFracture/io/CrackFaces.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <utility>

namespace btfracture {
namespace {

using Json = nlohmann::json;

// glTF constants (specification section 5)
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The binary chunk and the bufferViews/accessors that point into it.
class BinaryBuilder {
public:
    explicit BinaryBuilder(Json& document) : document_(document) {}

    // A float accessor of `components` (1, 3 or 4) per element, with min and max.
    int floats(const std::vector<float>& values, int components, const char* type, int target = 0) {
        const int count = static_cast<int>(values.size()) / components;
        std::vector<float> lo(components, std::numeric_limits<float>::max()),
            hi(components, std::numeric_limits<float>::lowest());
        for (size_t i = 0; i < values.size(); ++i) {
            lo[i % components] = std::min(lo[i % components], values[i]);
            hi[i % components] = std::max(hi[i % components], values[i]);
        }
        Json accessor = {{"bufferView", view(values.data(), values.size() * sizeof(float), target)},
                         {"componentType", kFloat},
                         {"count", count},
                         {"type", type}};
        accessor["min"] = lo;
        accessor["max"] = hi;
        document_["accessors"].push_back(accessor);
        return static_cast<int>(document_["accessors"].size()) - 1;
    }
    int indices(const std::vector<std::uint32_t>& values) {
        document_["accessors"].push_back(
            {{"bufferView", view(values.data(), values.size() * sizeof(std::uint32_t), kElementArrayBuffer)},
             {"componentType", kUnsignedInt},
             {"count", values.size()},
             {"type", "SCALAR"}});
        return static_cast<int>(document_["accessors"].size()) - 1;
    }
    const std::vector<char>& bytes() const { return bytes_; }

private:
    int view(const void* data, size_t size, int target) {
        Json v = {{"buffer", 0}, {"byteOffset", bytes_.size()}, {"byteLength", size}};
        if (target != 0) v["target"] = target;
        const char* begin = static_cast<const char*>(data);
        bytes_.insert(bytes_.end(), begin, begin + size);
        bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);  // 4-byte alignment of the next view
        document_["bufferViews"].push_back(v);
        return static_cast<int>(document_["bufferViews"].size()) - 1;
    }

    Json& document_;
    std::vector<char> bytes_;
};

Json material(const SurfaceMaterial& m) {
    return {{"name", m.name},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {m.rgb[0], m.rgb[1], m.rgb[2], 1.0}},
              {"metallicFactor", 0.0},
              {"roughnessFactor", 0.8}}}};
}

void append(std::vector<float>& out, const Eigen::Vector3d& v) {
    out.insert(out.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
}

// Unit quaternions (x, y, z, w) in float, each on the side of the previous one so that linear
// interpolation takes the short way.
std::vector<float> rotations(const std::vector<Eigen::Quaterniond>& orientations) {
    std::vector<float> out;
    Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
    for (size_t i = 0; i < orientations.size(); ++i) {
        Eigen::Quaterniond q = orientations[i].normalized();
        if (i > 0 && q.dot(previous) < 0.0) q.coeffs() = -q.coeffs();
        previous = q;
        Eigen::Vector4f f = q.coeffs().cast<float>();  // x, y, z, w
        f.normalize();
        out.insert(out.end(), {f.x(), f.y(), f.z(), f.w()});
    }
    return out;
}

}  // namespace

void writeGlb(const std::string& path, const std::vector<double>& times,
              const std::vector<GltfBody>& bodies) {
    const auto fail = [&](const std::string& what) { throw Error("glTF file '" + path + "': " + what); };
    if (times.empty()) fail("no sample times");
    for (size_t i = 1; i < times.size(); ++i)
        if (!(times[i] > times[i - 1])) fail("sample times must increase");

    Json document = {{"asset", {{"version", "2.0"}, {"generator", "btFracture"}}},
                     {"scene", 0},
                     {"scenes", Json::array({Json::object({{"nodes", Json::array()}})})},
                     {"nodes", Json::array()},
                     {"meshes", Json::array()},
                     {"materials", Json::array({material(kOutsideMaterial), material(kInteriorMaterial)})},
                     {"accessors", Json::array()},
                     {"bufferViews", Json::array()}};
    BinaryBuilder binary(document);
    Json channels = Json::array(), samplers = Json::array();
    std::map<std::pair<int, int>, int> timeAccessors;  // (first sample, count) -> accessor
    const auto timeAccessor = [&](int first, int count) {
        const auto found = timeAccessors.find({first, count});
        if (found != timeAccessors.end()) return found->second;
        const std::vector<float> t(times.begin() + first, times.begin() + first + count);
        return timeAccessors[{first, count}] = binary.floats(t, 1, "SCALAR");
    };
    const auto animate = [&](int node, const char* property, int input, int output,
                             const char* interpolation) {
        samplers.push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
        channels.push_back(
            {{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", property}}}});
    };

    for (const GltfBody& body : bodies) {
        const int samples = static_cast<int>(body.positions.size());
        const int end = body.firstSample + samples;  // first sample without the body
        if (samples == 0 || body.orientations.size() != body.positions.size() || body.firstSample < 0 ||
            end > static_cast<int>(times.size()) || (body.removed && end >= static_cast<int>(times.size())))
            fail("body '" + body.name + "' has samples outside the sample times");
        if (body.surface.triangles.empty()) fail("body '" + body.name + "' has no triangles");
        if (!body.crackFaces.empty() && body.crackFaces.size() != body.surface.triangles.size())
            fail("body '" + body.name + "': one crack flag per triangle expected");

        std::vector<float> positions;
        for (const auto& v : body.surface.vertices) append(positions, v);
        const int position = binary.floats(positions, 3, "VEC3", kArrayBuffer);
        Json primitives = Json::array();
        for (const int interior : {0, 1}) {
            std::vector<std::uint32_t> indices;
            for (size_t t = 0; t < body.surface.triangles.size(); ++t) {
                const bool crack = !body.crackFaces.empty() && body.crackFaces[t];
                if (crack != (interior == 1)) continue;
                for (int k = 0; k < 3; ++k)
                    indices.push_back(static_cast<std::uint32_t>(body.surface.triangles[t][k]));
            }
            if (indices.empty()) continue;
            primitives.push_back({{"attributes", {{"POSITION", position}}},
                                  {"indices", binary.indices(indices)},
                                  {"material", interior}});
        }
        document["meshes"].push_back({{"name", body.name}, {"primitives", primitives}});

        const int node = static_cast<int>(document["nodes"].size());
        const std::vector<float> rotation = rotations(body.orientations);
        Json n = {{"name", body.name},
                  {"mesh", document["meshes"].size() - 1},
                  {"translation",
                   {static_cast<float>(body.positions[0].x()), static_cast<float>(body.positions[0].y()),
                    static_cast<float>(body.positions[0].z())}},
                  {"rotation", {rotation[0], rotation[1], rotation[2], rotation[3]}}};
        if (body.firstSample > 0) n["scale"] = {0.0, 0.0, 0.0};
        document["nodes"].push_back(n);
        document["scenes"][0]["nodes"].push_back(node);

        bool moves = false;
        for (int i = 1; i < samples; ++i)
            moves = moves || body.positions[i] != body.positions[0] ||
                    body.orientations[i].coeffs() != body.orientations[0].coeffs();
        if (moves) {
            std::vector<float> translation;
            for (const auto& p : body.positions) append(translation, p);
            const int input = timeAccessor(body.firstSample, samples);
            animate(node, "translation", input, binary.floats(translation, 3, "VEC3"), "LINEAR");
            animate(node, "rotation", input, binary.floats(rotation, 4, "VEC4"), "LINEAR");
        }
        // Visibility: scale 0 before the body appears and from its removal on.
        std::vector<float> keyTimes, scales;
        const auto key = [&](double time, float scale) {
            keyTimes.push_back(static_cast<float>(time));
            scales.insert(scales.end(), {scale, scale, scale});
        };
        if (body.firstSample > 0) key(times[0], 0.0f);
        if (body.firstSample > 0 || body.removed) key(times[body.firstSample], 1.0f);
        if (body.removed) key(times[end], 0.0f);
        if (!keyTimes.empty())
            animate(node, "scale", binary.floats(keyTimes, 1, "SCALAR"), binary.floats(scales, 3, "VEC3"),
                    "STEP");
    }
    if (!channels.empty())
        document["animations"] = Json::array(
            {Json::object({{"name", "simulation"}, {"channels", channels}, {"samplers", samplers}})});
    document["buffers"] = Json::array({Json::object({{"byteLength", binary.bytes().size()}})});

    std::string json = document.dump();
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const std::vector<char>& bin = binary.bytes();
    const auto word = [](std::ofstream& out, std::uint32_t value) {
        const unsigned char b[4] = {static_cast<unsigned char>(value), static_cast<unsigned char>(value >> 8),
                                    static_cast<unsigned char>(value >> 16),
                                    static_cast<unsigned char>(value >> 24)};
        out.write(reinterpret_cast<const char*>(b), 4);
    };
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) fail(std::string("cannot create it: ") + std::strerror(errno));
    word(out, 0x46546C67u);  // "glTF"
    word(out, 2);
    word(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    word(out, static_cast<std::uint32_t>(json.size()));
    word(out, 0x4E4F534Au);  // "JSON"
    out.write(json.data(), static_cast<std::streamsize>(json.size()));
    word(out, static_cast<std::uint32_t>(bin.size()));
    word(out, 0x004E4942u);  // "BIN\0"
    out.write(bin.data(), static_cast<std::streamsize>(bin.size()));
    out.close();
    if (out.fail()) fail(std::string("writing failed: ") + std::strerror(errno));
}

}  // namespace btfracture
