// SPDX-License-Identifier: Zlib
#pragma once
// Preview frames of a SceneWorld for the runner's PNG output: a camera that follows the bodies
// that move, one colour per body, the frame's time as a label.
#include <btFracture/io/Image.h>
#include <btFracture/io/Rasterizer.h>
#include <btFracture/io/RenderSettings.h>

#include <map>
#include <optional>
#include <string>

namespace btfracture {

class SceneWorld;

class ScenePreview {
public:
    // The camera looks from settings.view at the bounding box of the bodies that move, as they
    // are now (of the static ones but planes when nothing moves), with "up" against gravity (+y
    // without gravity). Each body gets a colour by its position in the scene: static bodies
    // grey, the others from an 8-colour palette.
    ScenePreview(const SceneWorld& world, const RenderSettings& settings);

    // The world as it is now (reuses one rasterizer's buffers from frame to frame). The camera
    // follows the action: its box grows to hold every dynamic body (fragments included) as it
    // is now, and never shrinks, so the view widens smoothly as pieces fly apart.
    Image render(const SceneWorld& world);
    // Writes `text` (e.g. "t = 0.400 s") into the top-left corner, scaled with the image height.
    void label(Image& image, const std::string& text) const;

    // Colour of the body named `name`. A fragment named "<body>_f<k>" (possibly repeated,
    // "bunny_f3_f1") takes its original body's hue, brightened or darkened by its name, so that
    // neighbouring fragments differ and a fragment keeps its colour from frame to frame.
    Rgb colourOf(const std::string& name) const;

    const Camera& camera() const { return camera_; }
    static Rgb background() { return Rgb{236, 239, 243}; }

private:
    RenderSettings settings_;
    Eigen::AlignedBox3d box_;  // what the camera frames
    Eigen::Vector3d up_;
    Camera camera_;
    std::map<std::string, Rgb> colours_;  // original bodies by name
    std::optional<Rasterizer> rasterizer_;
};

}  // namespace btfracture
