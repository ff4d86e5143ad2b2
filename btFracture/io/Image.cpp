// SPDX-License-Identifier: Zlib
#include <btFracture/io/Image.h>

#include <btFracture/core/Error.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace btfracture {

namespace {
constexpr int kMaxSize = 16384;

std::uint8_t toByte(double unit) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}
}  // namespace

Rgb rgbFromUnit(double r, double g, double b) {
    return Rgb{toByte(r), toByte(g), toByte(b)};
}

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
    if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize)
        throw Error("image size " + std::to_string(width) + " x " + std::to_string(height) + " outside [1, " +
                    std::to_string(kMaxSize) + "]");
    pixels_.assign(static_cast<size_t>(width) * height, fill);
}

void Image::plot(int x, int y, Rgb colour) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) at(x, y) = colour;
}

void Image::fillRect(int x, int y, int width, int height, Rgb colour) {
    const int x0 = std::max(x, 0), y0 = std::max(y, 0);
    const int x1 = std::min(x + width, width_), y1 = std::min(y + height, height_);
    for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) at(i, j) = colour;
}

void Image::drawLine(int x0, int y0, int x1, int y1, Rgb colour, int thickness) {
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    const int lo = -(thickness - 1) / 2, hi = thickness / 2;
    int error = dx + dy;
    for (;;) {
        for (int j = lo; j <= hi; ++j)
            for (int i = lo; i <= hi; ++i) plot(x0 + i, y0 + j, colour);
        if (x0 == x1 && y0 == y1) break;
        const int e2 = 2 * error;
        if (e2 >= dy) {
            error += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            error += dx;
            y0 += sy;
        }
    }
}

void Image::blit(const Image& source, int x, int y) {
    for (int j = 0; j < source.height(); ++j)
        for (int i = 0; i < source.width(); ++i) plot(x + i, y + j, source.at(i, j));
}

Image Image::resized(int width, int height) const {
    if (width > width_ || height > height_)
        throw Error("Image::resized enlarges " + std::to_string(width_) + " x " + std::to_string(height_) +
                    " to " + std::to_string(width) + " x " + std::to_string(height) +
                    "; only reduction is supported");
    Image out(width, height);
    const double sx = static_cast<double>(width_) / width, sy = static_cast<double>(height_) / height;
    for (int j = 0; j < height; ++j) {
        const double top = j * sy, bottom = (j + 1) * sy;
        for (int i = 0; i < width; ++i) {
            const double left = i * sx, right = (i + 1) * sx;
            double sum[3] = {0, 0, 0}, weight = 0;
            for (int v = static_cast<int>(top); v < std::min(height_, static_cast<int>(std::ceil(bottom)));
                 ++v) {
                const double wy = std::min<double>(v + 1, bottom) - std::max<double>(v, top);
                for (int u = static_cast<int>(left); u < std::min(width_, static_cast<int>(std::ceil(right)));
                     ++u) {
                    const double w = wy * (std::min<double>(u + 1, right) - std::max<double>(u, left));
                    const Rgb& p = at(u, v);
                    sum[0] += w * p.r;
                    sum[1] += w * p.g;
                    sum[2] += w * p.b;
                    weight += w;
                }
            }
            out.at(i, j) =
                rgbFromUnit(sum[0] / weight / 255.0, sum[1] / weight / 255.0, sum[2] / weight / 255.0);
        }
    }
    return out;
}

}  // namespace btfracture
