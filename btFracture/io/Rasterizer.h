// SPDX-License-Identifier: Zlib
#pragma once
// A small software rasterizer for headless preview images: triangles with a z-buffer, flat or
// Gouraud shading under one fixed light (from the upper left behind the camera, plus ambient),
// an orthographic or perspective camera. Deterministic: the same calls give the same pixels.
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/io/Image.h>
#include <btFracture/io/RenderSettings.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace btfracture {

struct Camera {
    Projection projection = Projection::Perspective;
    Eigen::Vector3d eye = Eigen::Vector3d(0, 0, 5);
    // Orthonormal, right-handed: right = forward x up.
    Eigen::Vector3d forward = -Eigen::Vector3d::UnitZ(), up = Eigen::Vector3d::UnitY(),
                    right = Eigen::Vector3d::UnitX();
    double verticalFov = 0.6;    // perspective: full vertical opening angle [rad]
    double halfHeight = 1.0;     // orthographic: half the visible height [m]
    double nearDistance = 0.01;  // geometry closer than this along `forward` is clipped [m]

    // Looks from direction `view` (from the box's centre towards the camera) at `box`, framing
    // its bounding sphere with a 5 % margin for an image of aspect width / height. `up` is the
    // world's up direction (made orthogonal to the view; any other axis when they are parallel).
    static Camera framing(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& view,
                          const Eigen::Vector3d& up, Projection projection, double aspect);
};

class Rasterizer {
public:
    // Which faces are drawn: closed meshes cull faces turned away from the camera; open surfaces
    // (a plane's display square) show both sides.
    enum class Faces { Front, Both };

    // Clears to `background`. Renders internally at settings.supersampling times the size.
    Rasterizer(const RenderSettings& settings, const Camera& camera, Rgb background);

    // Starts a new picture on the same buffers (no reallocation between frames).
    void clear(Rgb background);

    // Draws `mesh` (world coordinates, counter-clockwise seen from outside) in `colour`.
    void draw(const TriangleMesh& mesh, Rgb colour, Faces faces = Faces::Front);

    // The picture so far, reduced to settings.width x settings.height.
    Image image() const;

private:
    struct ScreenVertex {
        double x, y;   // pixel coordinates of the internal buffer (y down)
        double depth;  // larger is nearer: 1/z (perspective) or -z (orthographic)
        Eigen::Vector3d colour;
    };
    void fillTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c);
    ScreenVertex project(const Eigen::Vector3d& cameraPoint, const Eigen::Vector3d& colour) const;

    RenderSettings settings_;
    Camera camera_;
    int width_, height_;         // internal buffer size
    Eigen::Vector3d light_;      // unit vector towards the light, world frame
    std::vector<float> colour_;  // internal buffer: r, g, b per sample in [0, 1]
    std::vector<double> depth_;
};

}  // namespace btfracture
