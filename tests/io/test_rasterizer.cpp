// SPDX-License-Identifier: Zlib
// The preview renderer: silhouettes against analytic projected areas, depth order, lighting,
// determinism, PNG round trips, contact sheets, and the preview camera following the action.
#include <btFracture/core/Error.h>
#include <btFracture/core/Primitives.h>
#include <btFracture/io/BitmapFont.h>
#include <btFracture/io/ContactSheet.h>
#include <btFracture/io/Image.h>
#include <btFracture/io/MeshReader.h>
#include <btFracture/io/PngFile.h>
#include <btFracture/io/Rasterizer.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/ScenePreview.h>
#include <btFracture/io/SceneWorld.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

using namespace btfracture;

namespace {

const Rgb kBackground{255, 255, 255};
const Rgb kRed{200, 30, 30}, kBlue{30, 30, 200};

TriangleMesh unitCube(const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
    TriangleMesh cube = makeBox(Eigen::Vector3d::Constant(0.5));
    for (auto& v : cube.vertices) v += centre;
    return cube;
}

int coveredPixels(const Image& image) {
    int count = 0;
    for (const Rgb& p : image.pixels()) count += p != kBackground ? 1 : 0;
    return count;
}

RenderSettings settings(int width, int height, Projection projection, int supersampling = 1) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.projection = projection;
    s.supersampling = supersampling;
    return s;
}

std::string bytesOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "btfracture_test_rasterizer";
    std::filesystem::create_directories(dir);
    return dir / name;
}

}  // namespace

// Orthographic projection of a unit cube along the unit direction d covers |dx| + |dy| + |dz|
// square metres (half the sum of |n.d| A over its six faces). At 400 x 400 pixels the cube spans
// about 200 pixels; sampling pixel centres misclassifies at most the ~800 boundary pixels, half
// of them each way, so the measured area is asserted to 1 %.
TEST(Rasterizer, OrthographicCubeSilhouetteMatchesProjectedArea) {
    const Eigen::Vector3d views[] = {{0, 0, 1}, {1, 0, 1}, {1, 0.6, 1.6}, {-2, 3, 1}};
    for (const Eigen::Vector3d& view : views) {
        Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
        const RenderSettings s = settings(400, 400, Projection::Orthographic);
        Camera camera = Camera::framing(box, view, Eigen::Vector3d::UnitY(), Projection::Orthographic, 1.0);
        camera.halfHeight = 1.0;  // 200 pixels per metre
        Rasterizer rasterizer(s, camera, kBackground);
        rasterizer.draw(unitCube(), kRed);
        const Eigen::Vector3d d = view.normalized();
        const double expected = d.cwiseAbs().sum() * 200.0 * 200.0;
        const double measured = coveredPixels(rasterizer.image());
        EXPECT_NEAR(measured / expected, 1.0, 0.01) << "view " << view.transpose();
    }
}

// Perspective, face-on: the front face at distance D - 1/2 projects to a square of side
// f / (D - 1/2) pixels with f = (h / 2) / tan(fov / 2); the side faces are edge-on and hidden.
TEST(Rasterizer, PerspectiveFrontFaceMatchesPinholeProjection) {
    Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
    const RenderSettings s = settings(480, 360, Projection::Perspective);
    const Camera camera = Camera::framing(box, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(),
                                          Projection::Perspective, 480.0 / 360.0);
    const double distance = camera.eye.z();
    const double focal = 0.5 * 360 / std::tan(0.5 * camera.verticalFov);
    const double side = focal / (distance - 0.5);
    Rasterizer rasterizer(s, camera, kBackground);
    rasterizer.draw(unitCube(), kRed);
    EXPECT_NEAR(coveredPixels(rasterizer.image()) / (side * side), 1.0, 4.0 * 4.0 * side / (side * side));
    // The framing keeps the whole cube inside the picture: the border rows and columns are empty.
    const Image image = rasterizer.image();
    for (int x = 0; x < image.width(); ++x) {
        EXPECT_EQ(image.at(x, 0), kBackground);
        EXPECT_EQ(image.at(x, image.height() - 1), kBackground);
    }
}

// The nearer of two overlapping cubes wins in the overlap, whichever is drawn first.
TEST(Rasterizer, DepthBufferKeepsTheNearestSurface) {
    Eigen::AlignedBox3d box(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 2));
    const RenderSettings s = settings(200, 200, Projection::Perspective);
    const Camera camera = Camera::framing(box, Eigen::Vector3d(0.3, 0.2, 1.0), Eigen::Vector3d::UnitY(),
                                          Projection::Perspective, 1.0);
    const TriangleMesh nearCube = unitCube(Eigen::Vector3d(0, 0, 1.2)),
                       farCube = unitCube(Eigen::Vector3d(0.2, 0.2, 0));
    for (int order = 0; order < 2; ++order) {
        Rasterizer rasterizer(s, camera, kBackground);
        if (order == 0) {
            rasterizer.draw(farCube, kBlue);
            rasterizer.draw(nearCube, kRed);
        } else {
            rasterizer.draw(nearCube, kRed);
            rasterizer.draw(farCube, kBlue);
        }
        const Image image = rasterizer.image();
        const Rgb centre = image.at(100, 100);
        EXPECT_GT(centre.r, centre.b) << "order " << order;  // red cube in front
        int blue = 0;
        for (const Rgb& p : image.pixels()) blue += p.b > p.r ? 1 : 0;
        EXPECT_GT(blue, 100) << "the far cube still shows beside the near one";
    }
}

// The light comes from the upper left behind the camera: on a sphere seen head-on, the
// brightest pixel lies in the upper-left quadrant, the darkest lit pixel in the lower right; flat
// shading gives one colour per triangle, Gouraud a smooth gradient (more distinct colours).
TEST(Rasterizer, LightingAndShadingModes) {
    const TriangleMesh sphere = makeGeodesicSphere(1.0, 8);
    Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1));
    int distinct[2] = {0, 0};
    for (Shading shading : {Shading::Flat, Shading::Gouraud}) {
        RenderSettings s = settings(160, 160, Projection::Orthographic);
        s.shading = shading;
        const Camera camera = Camera::framing(box, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(),
                                              Projection::Orthographic, 1.0);
        Rasterizer rasterizer(s, camera, kBackground);
        rasterizer.draw(sphere, Rgb{200, 200, 200});
        const Image image = rasterizer.image();
        int bright = -1, bx = 0, by = 0;
        std::set<int> colours;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const Rgb p = image.at(x, y);
                if (p == kBackground) continue;
                colours.insert(p.r);
                if (p.r > bright) {
                    bright = p.r;
                    bx = x;
                    by = y;
                }
            }
        EXPECT_LT(bx, 80);
        EXPECT_LT(by, 80);
        // Brightest: ambient + diffuse = full base colour (200), within one shading step.
        EXPECT_NEAR(bright, 200, shading == Shading::Flat ? 6 : 2);
        distinct[shading == Shading::Flat ? 0 : 1] = static_cast<int>(colours.size());
    }
    EXPECT_GT(distinct[1], distinct[0]);
}

// Same input, same bytes: two renders of the bunny agree pixel for pixel and as PNG files.
TEST(Rasterizer, DeterministicPixelsAndPngBytes) {
    TriangleMesh bunny = readMesh(std::string(BTFRACTURE_MESH_DIR) + "/bunny.obj");
    Eigen::AlignedBox3d box;
    for (const auto& v : bunny.vertices) box.extend(v);
    std::string bytes[2];
    Image images[2];
    for (int run = 0; run < 2; ++run) {
        RenderSettings s = settings(320, 240, Projection::Perspective, 2);
        const Camera camera =
            Camera::framing(box, s.view, Eigen::Vector3d::UnitY(), s.projection, 320.0 / 240.0);
        Rasterizer rasterizer(s, camera, kBackground);
        rasterizer.draw(bunny, kRed);
        images[run] = rasterizer.image();
        const auto path = scratch("bunny_" + std::to_string(run) + ".png");
        writePng(path.string(), images[run]);
        bytes[run] = bytesOf(path.string());
    }
    EXPECT_GT(coveredPixels(images[0]), 5000);
    EXPECT_TRUE(images[0].pixels() == images[1].pixels());
    EXPECT_FALSE(bytes[0].empty());
    EXPECT_EQ(bytes[0], bytes[1]);
}

// A plane's display square passing behind the camera is clipped at the near plane instead of
// wrapping around: it fills the lower part of the picture and nothing above the horizon.
TEST(Rasterizer, NearPlaneClipsGeometryBehindTheCamera) {
    TriangleMesh ground;
    ground.vertices = {{-50, 0, -50}, {50, 0, -50}, {50, 0, 50}, {-50, 0, 50}};
    ground.triangles = {{0, 2, 1}, {0, 3, 2}};
    Camera camera;
    camera.eye = Eigen::Vector3d(0, 1, 0);  // 1 m above the ground, looking along -z
    RenderSettings s = settings(100, 100, Projection::Perspective);
    Rasterizer rasterizer(s, camera, kBackground);
    rasterizer.draw(ground, kBlue, Rasterizer::Faces::Both);
    const Image image = rasterizer.image();
    for (int x = 0; x < 100; ++x) {
        EXPECT_EQ(image.at(x, 40), kBackground) << "above the horizon";
        EXPECT_NE(image.at(x, 99), kBackground) << "ground below";
    }
}

TEST(Image, PngRoundTripAndErrors) {
    Image image(37, 21, Rgb{1, 2, 3});
    image.fillRect(5, 5, 10, 4, Rgb{250, 128, 0});
    image.drawLine(0, 20, 36, 0, Rgb{0, 255, 0});
    drawText(image, 2, 2, "t = 1.5 s", Rgb{0, 0, 0});
    const auto path = scratch("roundtrip.png");
    writePng(path.string(), image);
    const Image back = readPng(path.string());
    ASSERT_EQ(back.width(), 37);
    ASSERT_EQ(back.height(), 21);
    EXPECT_TRUE(back.pixels() == image.pixels());

    try {
        writePng("/no/such/folder/x.png", image);
        ADD_FAILURE() << "unwritable path accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write PNG '/no/such/folder/x.png'"), std::string::npos);
    }
    const auto garbage = scratch("garbage.png");
    std::ofstream(garbage) << "not a png";
    EXPECT_THROW(readPng(garbage.string()), Error);
    EXPECT_THROW(Image(0, 5), Error);
}

// Box filter: each output pixel is the mean of the source pixels it covers.
TEST(Image, ResizedAveragesCoveredPixels) {
    Image checker(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) checker.at(x, y) = (x + y) % 2 ? Rgb{255, 255, 255} : Rgb{0, 0, 0};
    const Image half = checker.resized(2, 2);
    for (const Rgb& p : half.pixels()) EXPECT_EQ(p, (Rgb{128, 128, 128}));
    const Image third = Image(3, 1, Rgb{90, 90, 90}).resized(2, 1);  // fractional footprints
    EXPECT_EQ(third.at(0, 0), (Rgb{90, 90, 90}));
    EXPECT_THROW(checker.resized(8, 8), Error);
}

TEST(ContactSheet, SelectionAndLayout) {
    EXPECT_EQ(contactSheetSelection(3, 16), (std::vector<size_t>{0, 1, 2}));
    EXPECT_EQ(contactSheetSelection(10, 4), (std::vector<size_t>{0, 3, 6, 9}));
    EXPECT_EQ(contactSheetSelection(47, 16).size(), 16u);
    EXPECT_EQ(contactSheetSelection(47, 16).back(), 46u);
    EXPECT_TRUE(contactSheetSelection(0, 16).empty());

    std::vector<Image> frames;
    std::vector<std::string> labels;
    for (int k = 0; k < 5; ++k) {
        frames.emplace_back(80, 60, Rgb{static_cast<std::uint8_t>(40 * k), 0, 0});
        labels.push_back("f" + std::to_string(k));
    }
    const Image sheet = contactSheet(frames, labels, 3, 40);  // cells of 40 x 30, two rows
    const int cellHeight = 30 + textHeight() + 2;
    EXPECT_EQ(sheet.width(), 4 + 3 * (40 + 4));
    EXPECT_EQ(sheet.height(), 4 + 2 * (cellHeight + 4));
    EXPECT_EQ(sheet.at(4 + 20, 4 + 15), (Rgb{0, 0, 0}));                          // frame 0
    EXPECT_EQ(sheet.at(4 + 44 + 20, 4 + cellHeight + 4 + 15), (Rgb{160, 0, 0}));  // frame 4: row 1, column 1
    EXPECT_THROW(contactSheet({}, {}, 3, 40), Error);
    frames.emplace_back(10, 10);
    EXPECT_THROW(contactSheet(frames, {}, 3, 40), Error);
}

TEST(ScenePreview, CameraFollowsABodyThatLeavesTheStartFrame) {
    // No gravity: a static box at the origin and a box flying off along x at 10 m/s.
    RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.supersampling = 1;
    SceneWorld world(parseScene(R"({"world": {"dt": 0.01, "gravity": [0, 0, 0]},
        "bodies": [{"name": "post", "shape": {"type": "box", "half_extents": [0.5, 0.5, 0.5]}, "mass": 0},
                   {"name": "flyer", "shape": {"type": "box", "half_extents": [0.5, 0.5, 0.5]},
                    "position": [2, 0, 0], "linear_velocity": [10, 0, 0]}]})",
                                "test.json", "."));
    ScenePreview preview(world, settings);
    const auto flyerPixels = [&](const Image& image) {  // orange, lit or in shade; the rest is grey
        int n = 0;
        for (const Rgb& p : image.pixels()) n += p.r > p.b + 60 ? 1 : 0;
        return n;
    };
    EXPECT_GT(flyerPixels(preview.render(world)), 100);
    const Camera start = preview.camera();
    for (int frame = 0; frame < 200; ++frame) world.stepFrame();  // 20 m further
    // A camera that stayed at the start frame sees nothing of the flyer now; this one follows.
    EXPECT_GT(flyerPixels(preview.render(world)), 10);
    EXPECT_NE(preview.camera().eye, start.eye);
}
