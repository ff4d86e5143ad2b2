// SPDX-License-Identifier: Zlib
// The runner's preview output on the Fig. 1 scene (demos/scenes/column_bunny.json, ~16,000
// triangles with the ground square): render time per frame for each image setting, PNG encode
// time, and the contact sheet. Best of 5 runs; headline lines "METRIC <name> <value> <unit>".
#include "BestOf.h"

#include <btFracture/core/Timer.h>
#include <btFracture/io/ContactSheet.h>
#include <btFracture/io/PngFile.h>
#include <btFracture/io/SceneFile.h>
#include <btFracture/io/ScenePreview.h>
#include <btFracture/io/SceneWorld.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using namespace btfracture;

int main() {
    const Scene scene = readSceneFile(std::string(BTFRACTURE_MESH_DIR) + "/../scenes/column_bunny.json");
    SceneWorld world(scene);
    for (int i = 0; i < 60; ++i) world.stepFrame();  // the ball close to the column

    struct Case {
        const char* name;
        int width, height, supersampling;
        Shading shading;
        Projection projection;
    };
    const Case cases[] = {
        {"640x480 gouraud ss2 (default)", 640, 480, 2, Shading::Gouraud, Projection::Perspective},
        {"640x480 gouraud ss1", 640, 480, 1, Shading::Gouraud, Projection::Perspective},
        {"640x480 flat ss2", 640, 480, 2, Shading::Flat, Projection::Perspective},
        {"640x480 ortho ss2", 640, 480, 2, Shading::Gouraud, Projection::Orthographic},
        {"1280x960 gouraud ss2", 1280, 960, 2, Shading::Gouraud, Projection::Perspective}};
    std::printf("%-32s %12s %12s\n", "setting", "render [ms]", "encode [ms]");
    const std::string png = (std::filesystem::temp_directory_path() / "bench_preview.png").string();
    double defaultRender = 0.0, defaultEncode = 0.0;
    for (const Case& c : cases) {
        RenderSettings settings = scene.outputs.image;
        settings.width = c.width;
        settings.height = c.height;
        settings.supersampling = c.supersampling;
        settings.shading = c.shading;
        settings.projection = c.projection;
        ScenePreview preview(world, settings);
        Image frame;
        const double render = bestOf(5, [&] { frame = preview.render(world); });
        const double encode = bestOf(5, [&] { writePng(png, frame); });
        std::printf("%-32s %12.2f %12.2f\n", c.name, 1e3 * render, 1e3 * encode);
        if (&c == &cases[0]) {
            defaultRender = render;
            defaultEncode = encode;
        }
    }
    ScenePreview preview(world, scene.outputs.image);
    std::vector<Image> thumbnails(16, preview.render(world).resized(160, 120));
    const double sheet =
        bestOf(5, [&] { contactSheet(thumbnails, std::vector<std::string>(16, "t = 0.240 s"), 4, 160); });
    std::printf("METRIC preview_render_640x480 %.2f ms\n", 1e3 * defaultRender);
    std::printf("METRIC preview_png_encode_640x480 %.2f ms\n", 1e3 * defaultEncode);
    std::printf("METRIC contact_sheet_16 %.2f ms\n", 1e3 * sheet);
    std::filesystem::remove(png);
    return 0;
}
