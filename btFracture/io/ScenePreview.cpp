// SPDX-License-Identifier: Zlib
#include <btFracture/io/ScenePreview.h>

#include <btFracture/core/Log.h>
#include <btFracture/io/BitmapFont.h>
#include <btFracture/io/SceneWorld.h>

#include <algorithm>
#include <cctype>

namespace btfracture {
namespace {

// Distinct, print-friendly hues for the bodies that move.
constexpr Rgb kPalette[] = {{217, 95, 2},   {27, 158, 119}, {117, 112, 179}, {231, 41, 138},
                            {102, 166, 30}, {230, 171, 2},  {31, 120, 180},  {166, 118, 29}};
constexpr Rgb kStatic{176, 176, 172};
constexpr Rgb kPlane{196, 194, 188};
constexpr Rgb kLabel{40, 40, 48};

// "bunny_f3_f12" -> "bunny"; names without a fragment suffix stay as they are.
std::string originalName(std::string name) {
    for (;;) {
        const size_t mark = name.rfind("_f");
        if (mark == std::string::npos || mark + 2 == name.size()) return name;
        const bool digits = std::all_of(name.begin() + static_cast<std::ptrdiff_t>(mark) + 2, name.end(),
                                        [](unsigned char c) { return std::isdigit(c); });
        if (!digits) return name;
        name.erase(mark);
    }
}

// FNV-1a: a stable hash of a name (std::hash may differ between library versions).
std::uint32_t stableHash(const std::string& text) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : text) h = (h ^ c) * 16777619u;
    return h;
}

}  // namespace

ScenePreview::ScenePreview(const SceneWorld& world, const RenderSettings& settings) : settings_(settings) {
    const Scene& scene = world.scene();
    Eigen::AlignedBox3d moving, fixed;  // bodies that move; static bodies but planes
    size_t colours = 0;
    for (size_t i = 0; i < world.bodies().size(); ++i) {
        const SceneBody& description = scene.bodies[i];
        const bool plane = description.shape.type == SceneShapeType::Plane;
        colours_[description.name] = plane ? kPlane
                                     : description.isStatic()
                                         ? kStatic
                                         : kPalette[colours++ % (sizeof kPalette / sizeof kPalette[0])];
        if (plane) continue;
        for (const auto& v : world.worldSurface(i).vertices)
            (description.isStatic() ? fixed : moving).extend(v);
    }
    Eigen::AlignedBox3d box = !moving.isEmpty() ? moving : fixed;
    if (box.isEmpty()) {
        logf(LogLevel::Info, scene.file,
             ": only planes in the scene; the preview camera frames 1 m around the origin");
        box.extend(Eigen::Vector3d::Constant(-1.0));
        box.extend(Eigen::Vector3d::Constant(1.0));
    }
    box_ = box;
    up_ = scene.world.gravity.norm() > 0.0 ? Eigen::Vector3d(-scene.world.gravity.normalized())
                                           : Eigen::Vector3d::UnitY();
    camera_ = Camera::framing(box_, settings.view, up_, settings.projection,
                              static_cast<double>(settings.width) / settings.height);
}

Rgb ScenePreview::colourOf(const std::string& name) const {
    const std::string original = originalName(name);
    const auto found = colours_.find(original);
    Rgb base = found != colours_.end() ? found->second : kStatic;
    if (original == name) return base;
    // Fragments: brightness between 0.7 and 1.15 of the original's, by name.
    const double factor = 0.7 + 0.45 * (stableHash(name) % 1000) / 999.0;
    return rgbFromUnit(factor * base.r / 255.0, factor * base.g / 255.0, factor * base.b / 255.0);
}

void ScenePreview::label(Image& image, const std::string& text) const {
    const int scale = std::max(1, image.height() / 240);
    drawText(image, 4 * scale, 4 * scale, text, kLabel, scale);
}

Image ScenePreview::render(const SceneWorld& world) {
    Eigen::AlignedBox3d box = box_;
    for (size_t i = 0; i < world.bodies().size(); ++i)
        if (world.bodies()[i].rigidBody->getInvMass() > 0)
            for (const auto& v : world.worldSurface(i).vertices) box.extend(v);
    if (box.min() != box_.min() || box.max() != box_.max()) {
        box_ = box;
        camera_ = Camera::framing(box_, settings_.view, up_, settings_.projection,
                                  static_cast<double>(settings_.width) / settings_.height);
        rasterizer_.reset();
    }
    if (rasterizer_)
        rasterizer_->clear(background());
    else
        rasterizer_.emplace(settings_, camera_, background());
    Rasterizer& rasterizer = *rasterizer_;
    for (size_t i = 0; i < world.bodies().size(); ++i) {
        const bool plane = world.bodies()[i].plane;
        rasterizer.draw(world.worldSurface(i), colourOf(world.bodies()[i].name),
                        plane ? Rasterizer::Faces::Both : Rasterizer::Faces::Front);
    }
    return rasterizer.image();
}

}  // namespace btfracture
