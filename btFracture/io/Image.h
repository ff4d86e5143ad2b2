// SPDX-License-Identifier: Zlib
#pragma once
// An 8-bit RGB raster image (row-major, origin at the top-left corner) with the few drawing
// operations the preview renderer and the plots need.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace btfracture {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
    bool operator!=(const Rgb& o) const { return !(*this == o); }
};

// Colour from floating-point channels in [0, 1] (clamped, rounded to nearest).
Rgb rgbFromUnit(double r, double g, double b);

class Image {
public:
    Image() = default;
    // Throws btfracture::Error for sizes outside [1, 16384].
    Image(int width, int height, Rgb fill = Rgb{});

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return pixels_.empty(); }
    Rgb& at(int x, int y) { return pixels_[static_cast<size_t>(y) * width_ + x]; }
    const Rgb& at(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
    const std::vector<Rgb>& pixels() const { return pixels_; }
    Rgb* data() { return pixels_.data(); }  // width * height packed RGB triples, row by row

    // Sets pixel (x, y) when it lies inside the image (drawing helpers clip through this).
    void plot(int x, int y, Rgb colour);
    void fillRect(int x, int y, int width, int height, Rgb colour);
    // Straight line between pixel centres, `thickness` pixels wide (Bresenham, square pen).
    void drawLine(int x0, int y0, int x1, int y1, Rgb colour, int thickness = 1);
    // Copies `source` with its top-left corner at (x, y), clipped to this image.
    void blit(const Image& source, int x, int y);

    // Box-filtered reduction to width x height (each output pixel averages the source pixels
    // it covers, with fractional weights at the borders). Throws Error when enlarging.
    Image resized(int width, int height) const;

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<Rgb> pixels_;
};

}  // namespace btfracture
