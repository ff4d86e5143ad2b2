// SPDX-License-Identifier: Zlib
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/io/MeshReader.h>
#include <btFracture/io/ObjReader.h>
#include <btFracture/io/ObjWriter.h>
#include <btFracture/io/PlyReader.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

const std::string kBad = std::string(BTFRACTURE_TEST_DATA_DIR) + "/bad_meshes/";
const std::string kFormats = std::string(BTFRACTURE_TEST_DATA_DIR) + "/formats/";
const std::string kMeshes = std::string(BTFRACTURE_MESH_DIR) + "/";

std::string loadError(const std::string& path) {
    try {
        readMesh(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Collects warnings while alive.
struct WarningCapture {
    std::vector<std::string> warnings;
    WarningCapture() {
        setLogSink([this](LogLevel level, const std::string& text) {
            if (level >= LogLevel::Warning) warnings.push_back(text);
        });
    }
    ~WarningCapture() { setLogSink(nullptr); }
};

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("btfracture_test_io_" + name)).string();
}

}  // namespace

// Every mesh shipped in demos/meshes loads as a closed, outward, self-intersection-free solid.
TEST(MeshReader, EveryShippedMeshLoads) {
    struct Expected {
        const char* file;
        size_t vertices, triangles;
        int components;
    };
    const Expected expected[] = {{"armadillo.obj", 26002, 52000, 1}, {"bowl.obj", 5858, 11712, 1},
                                 {"bunny.obj", 1839, 3674, 1},       {"column.obj", 6242, 12480, 1},
                                 {"fandisk.obj", 6475, 12946, 1},    {"spot.obj", 2930, 5856, 1},
                                 {"teapot.obj", 7850, 15704, 2}};
    size_t shipped = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kMeshes))
        if (entry.path().extension() == ".obj") ++shipped;
    EXPECT_EQ(shipped, std::size(expected)) << "a mesh was added to demos/meshes without a test entry";
    for (const auto& e : expected) {
        SCOPED_TRACE(e.file);
        WarningCapture capture;
        const TriangleMesh mesh = readMesh(kMeshes + e.file);
        EXPECT_TRUE(capture.warnings.empty()) << capture.warnings.front();
        EXPECT_EQ(mesh.vertices.size(), e.vertices);
        EXPECT_EQ(mesh.triangles.size(), e.triangles);
        const MeshDefects d = inspectMesh(mesh);
        EXPECT_TRUE(d.isClosedSolid()) << d.describe();
        EXPECT_EQ(d.components, e.components);  // the teapot's pot and lid are each closed
        EXPECT_GT(d.signedVolume, 0.0);
    }
}

TEST(MeshReader, ColumnIsTwoMetresTall) {
    const TriangleMesh column = readMesh(kMeshes + "column.obj");
    double lo = 1e9, hi = -1e9;
    for (const auto& v : column.vertices) {
        lo = std::min(lo, v.y());
        hi = std::max(hi, v.y());
    }
    EXPECT_DOUBLE_EQ(lo, 0.0);
    EXPECT_DOUBLE_EQ(hi, 2.0);
}

// Each hand-made bad file: the message names the file and the defect with its count.
TEST(MeshReader, DefectsAreReportedWithFileAndCount) {
    const std::pair<const char*, const char*> cases[] = {
        {"open.obj", "3 boundary edges (open mesh)"},
        {"nonmanifold_edge.obj", "1 non-manifold edge"},
        {"nonmanifold_vertex.obj", "1 non-manifold vertex"},
        {"inconsistent.obj", "3 inconsistently oriented edges"},
        {"degenerate.obj", "1 degenerate triangle"},
        {"nonfinite.obj", "1 non-finite vertex"},
        {"self_intersecting.obj", "3 self-intersecting triangle pairs"},
    };
    for (const auto& [file, defect] : cases) {
        const std::string message = loadError(kBad + file);
        EXPECT_TRUE(contains(message, kBad + file)) << message;
        EXPECT_TRUE(contains(message, defect)) << file << ": " << message;
    }
    // The single-defect files report nothing else.
    EXPECT_TRUE(contains(loadError(kBad + "open.obj"), "mesh: 3 boundary edges (open mesh)"));
    EXPECT_TRUE(contains(loadError(kBad + "nonmanifold_edge.obj"), "mesh: 1 non-manifold edge"));
    const std::string intersecting = loadError(kBad + "self_intersecting.obj");
    EXPECT_TRUE(contains(intersecting, "mesh: 3 self-intersecting triangle pairs")) << intersecting;
}

TEST(MeshReader, InsideOutLoadsFlippedWithWarning) {
    WarningCapture capture;
    const TriangleMesh mesh = readMesh(kBad + "inside_out.obj");
    ASSERT_EQ(capture.warnings.size(), 1u);
    EXPECT_TRUE(contains(capture.warnings[0], "inside_out.obj")) << capture.warnings[0];
    EXPECT_TRUE(contains(capture.warnings[0], "inside-out")) << capture.warnings[0];
    EXPECT_NEAR(inspectMesh(mesh).signedVolume, 1.0 / 6.0, 1e-15);
}

TEST(MeshReader, SyntaxErrorsNameFileAndLine) {
    const std::string vertex = loadError(kBad + "malformed_vertex.obj");
    EXPECT_TRUE(contains(
        vertex, kBad + "malformed_vertex.obj:4: expected a number for vertex coordinate 2, got 'abc'"))
        << vertex;
    const std::string index = loadError(kBad + "bad_index.obj");
    EXPECT_TRUE(
        contains(index, kBad + "bad_index.obj:7: vertex index 9 out of range (4 vertices defined so far)"))
        << index;
    const std::string ply = loadError(kBad + "truncated.ply");
    EXPECT_TRUE(contains(ply, kBad + "truncated.ply:") && contains(ply, "face 3: file ends early")) << ply;
    EXPECT_TRUE(
        contains(loadError(kBad + "unknown.stl"), "unsupported extension '.stl' (expected .obj or .ply)"));

    const std::pair<const char*, const char*> objCases[] = {
        {"v 1 2\n", "x.obj:1: expected 3 vertex coordinates after 'v'"},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", "x.obj:3: expected at least 3 vertex indices"},
        {"v 0 0 0\nf 1 0 1\n", "x.obj:2: vertex index 0 out of range"},
        {"v 0 0 0\nf 1 -2 1\n", "x.obj:2: vertex index -2 out of range"},
        {"v 0 0 0\nf 1/a 1 1\n",
         "x.obj:2: expected a face corner of the form i, i/t, i/t/n or i//n, got '1/a'"},
        {"# ok\nbogus 1 2\n", "x.obj:2: unknown OBJ record 'bogus'"},
    };
    for (const auto& [text, expected] : objCases) {
        try {
            parseObj(text, "x.obj");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            EXPECT_TRUE(contains(e.what(), expected)) << e.what();
        }
    }
    const std::pair<const char*, const char*> plyCases[] = {
        {"ply\nformat ascii 2.0\nend_header\n",
         "x.ply: header line 2: expected 'format ascii|binary_little_endian"},
        {"obj\n", "x.ply: header line 1: expected 'ply'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
         "x.ply: expected a 'vertex' and a 'face' element"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 zero\n3 0 0 0\n",
         "x.ply:10: vertex 0: expected a number for property 'z', got 'zero'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 5\n",
         "x.ply:11: face 0: vertex index 5 out of range (1 vertices)"},
        {"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n\x01\x02",
         "x.ply: vertex 0: file ends early in property 'x'"},
    };
    for (const auto& [text, expected] : plyCases) {
        try {
            parsePly(text, "x.ply");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            EXPECT_TRUE(contains(e.what(), expected)) << e.what();
        }
    }
}

// A header whose last line has no line end (a fuzzing find: the data offset ran past the end).
TEST(MeshReader, PlyHeaderAtEndOfFile) {
    // Both are bad files: the answer must be btfracture::Error (it was std::out_of_range).
    EXPECT_THROW(parsePly("ply\nformat ascii 1.0\nelement vertex 0\nend_header", "short.ply"), Error);
    EXPECT_THROW(
        parsePly("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nend_header\tdata",
                 "short.ply"),
        Error);
}

TEST(MeshReader, MissingFileNamesPath) {
    const std::string message = loadError(kBad + "does_not_exist.obj");
    EXPECT_TRUE(contains(message,
                         "cannot open mesh file '" + kBad + "does_not_exist.obj': No such file or directory"))
        << message;
}

// The cube in OBJ (every face form) and in ascii / binary little / big endian PLY reads the same.
TEST(MeshReader, ObjAndPlyFormatsAgree) {
    const TriangleMesh reference = readMesh(kFormats + "cube.obj");
    ASSERT_EQ(reference.vertices.size(), 8u);
    ASSERT_EQ(reference.triangles.size(), 12u);  // 6 quads, fan-split
    EXPECT_NEAR(computeMassProperties(reference).volume, 8.0, 1e-12);
    for (const char* file : {"cube_ascii.ply", "cube_binary_le.ply", "cube_binary_be.ply"}) {
        SCOPED_TRACE(file);
        const TriangleMesh mesh = readMesh(kFormats + file);
        ASSERT_EQ(mesh.vertices.size(), reference.vertices.size());
        for (size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_EQ(mesh.vertices[i], reference.vertices[i]);
        EXPECT_EQ(mesh.triangles, reference.triangles);
    }
    // Polygon splitting is announced once per file.
    std::vector<std::string> infos;
    setLogSink([&](LogLevel, const std::string& text) { infos.push_back(text); });
    readMesh(kFormats + "cube_binary_le.ply");
    setLogSink(nullptr);
    ASSERT_EQ(infos.size(), 1u);
    EXPECT_TRUE(contains(infos[0], "split 6 polygon faces (up to 4 corners)")) << infos[0];
}

TEST(ObjWriter, RoundTripIsExactAtFullPrecision) {
    const TriangleMesh original = readMesh(kMeshes + "spot.obj");
    TriangleMesh moved = original;
    for (auto& v : moved.vertices)
        v = 1.0 / 3.0 * v + Eigen::Vector3d(0.1, -2.0 / 7.0, 1e-3);  // no short decimals
    const std::string path = tempPath("roundtrip.obj");
    writeObj(path, moved, 17);
    const TriangleMesh back = readMesh(path);
    ASSERT_EQ(back.vertices.size(), moved.vertices.size());
    for (size_t i = 0; i < moved.vertices.size(); ++i) ASSERT_EQ(back.vertices[i], moved.vertices[i]) << i;
    EXPECT_EQ(back.triangles, moved.triangles);

    // Default precision: 9 significant digits, so relative error below 5e-9 of the magnitude.
    writeObj(path, moved);
    const TriangleMesh rounded = readMesh(path);
    for (size_t i = 0; i < moved.vertices.size(); ++i)
        EXPECT_LE((rounded.vertices[i] - moved.vertices[i]).cwiseAbs().maxCoeff(),
                  5e-9 * moved.vertices[i].cwiseAbs().maxCoeff());
    std::remove(path.c_str());
}

TEST(ObjWriter, SeveralNamedObjectsInOneFile) {
    const TriangleMesh cube = readMesh(kFormats + "cube.obj");
    TriangleMesh shifted = cube;
    for (auto& v : shifted.vertices) v.x() += 5.0;
    const std::string path = tempPath("objects.obj");
    {
        ObjWriter writer(path);
        writer.addObject("left", cube);
        writer.addObject("right", shifted);
        EXPECT_THROW(writer.addObject("bad name", cube), Error);
    }
    // Read back as one mesh: two closed parts, indices of the second continue after the first.
    const TriangleMesh both = readMesh(path);
    EXPECT_EQ(both.vertices.size(), 16u);
    EXPECT_EQ(inspectMesh(both).components, 2);
    EXPECT_NEAR(computeMassProperties(both).volume, 16.0, 1e-12);
    std::FILE* file = std::fopen(path.c_str(), "r");
    ASSERT_NE(file, nullptr);
    char line[256];
    std::vector<std::string> objects;
    while (std::fgets(line, sizeof line, file))
        if (line[0] == 'o') objects.emplace_back(line);
    std::fclose(file);
    EXPECT_EQ(objects, (std::vector<std::string>{"o left\n", "o right\n"}));
    std::remove(path.c_str());
    EXPECT_THROW(ObjWriter("/nonexistent-dir/x.obj"), Error);
}
