// SPDX-License-Identifier: Zlib
#pragma once
// Settings of the headless preview renderer (io/Rasterizer.h, io/ScenePreview.h); the scene
// file's outputs.image.
#include <Eigen/Core>

namespace btfracture {

enum class Projection { Perspective, Orthographic };
enum class Shading {
    Gouraud,  // colours lit per vertex (averaged normals; face normals at creases over 45 degrees),
              // interpolated
    Flat,     // one lit colour per triangle
};

struct RenderSettings {
    int width = 640;   // [pixels]
    int height = 480;  // [pixels]
    Projection projection = Projection::Perspective;
    Shading shading = Shading::Gouraud;
    // Direction from the scene's centre towards the camera (world frame, any length).
    Eigen::Vector3d view{1.0, 0.6, 1.6};
    // Samples per pixel along each axis, averaged (anti-aliasing); 1 = none.
    int supersampling = 2;
};

}  // namespace btfracture
