// SPDX-License-Identifier: Zlib
#include <btFracture/core/PortableMath.h>
#include <btFracture/io/BitmapFont.h>
#include <btFracture/io/Plot.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace btfracture {

namespace {

const Rgb kBlack{0, 0, 0}, kGrid{225, 225, 225}, kWhite{255, 255, 255};

struct Scale {
    bool log = false;
    double lo = 0.0, hi = 1.0;  // data range (log10 of it on log axes)
    double map(double v) const { return ((log ? pmath::log10(v) : v) - lo) / (hi - lo); }
    bool accepts(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

Scale makeScale(const std::vector<PlotSeries>& series, bool xAxis, bool log) {
    Scale s;
    s.log = log;
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& ps : series)
        for (const auto& p : ps.xy) {
            const double v = xAxis ? p.first : p.second, other = xAxis ? p.second : p.first;
            if (!s.accepts(v) || !std::isfinite(other)) continue;
            const double t = log ? pmath::log10(v) : v;
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
    if (!(lo <= hi)) lo = 0.0, hi = 1.0;
    if (log) {  // whole decades
        lo = std::floor(lo);
        hi = std::max(std::ceil(hi), lo + 1.0);
    } else {
        if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) lo -= 0.5, hi += 0.5;
        const double pad = 0.05 * (hi - lo);
        lo = (lo >= 0.0 && lo - pad < 0.0) ? 0.0 : lo - pad;
        hi += pad;
    }
    s.lo = lo;
    s.hi = hi;
    return s;
}

// Tick positions in data units: 1-2-5 steps (about six ticks) or decades.
std::vector<double> ticks(const Scale& s) {
    std::vector<double> out;
    if (s.log) {
        const int step = std::max(1, static_cast<int>(std::ceil((s.hi - s.lo) / 8.0)));
        for (int e = static_cast<int>(s.lo); e <= static_cast<int>(s.hi); e += step)
            out.push_back(pmath::pow(10.0, e));
        return out;
    }
    const double raw = (s.hi - s.lo) / 6.0, mag = pmath::pow(10.0, std::floor(pmath::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    for (double v = std::ceil(s.lo / step) * step; v <= s.hi + 1e-9 * step; v += step)
        out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return out;
}

std::string tickLabel(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

void drawMarker(Image& image, int x, int y, int shape, Rgb colour) {
    switch (shape % 4) {
        case 0:
            image.fillRect(x - 3, y - 3, 7, 7, colour);
            break;
        case 1:
            image.drawLine(x - 4, y - 4, x + 4, y + 4, colour, 2);
            image.drawLine(x - 4, y + 4, x + 4, y - 4, colour, 2);
            break;
        case 2:
            for (int d = 0; d <= 4; ++d)
                image.fillRect(x - (4 - d), y - d, 2 * (4 - d) + 1, 2 * d + 1, colour);
            break;
        default:
            image.drawLine(x - 4, y, x + 4, y, colour, 2);
            image.drawLine(x, y - 4, x, y + 4, colour, 2);
            break;
    }
}

}  // namespace

Rgb plotColour(int index) {
    static const Rgb palette[8] = {{31, 119, 180},  {214, 39, 40}, {44, 160, 44},   {255, 127, 14},
                                   {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};
    return palette[((index % 8) + 8) % 8];
}

Image plotChart(const PlotSpec& spec) {
    Image image(spec.width, spec.height, kWhite);
    const Scale sx = makeScale(spec.series, true, spec.x.logarithmic);
    const Scale sy = makeScale(spec.series, false, spec.y.logarithmic);
    // Legend to the right of the axes, so that it never hides a point.
    int legendRows = 0, widest = 0;
    for (const auto& ps : spec.series)
        if (!ps.label.empty()) ++legendRows, widest = std::max(widest, textWidth(ps.label));
    const int legendWidth = legendRows > 0 ? widest + 34 : 0;
    const int left = 72, right = spec.width - 16 - (legendWidth > 0 ? legendWidth + 8 : 0), top = 40,
              bottom = spec.height - 44;
    auto px = [&](double v) { return left + static_cast<int>(std::lround(sx.map(v) * (right - left))); };
    auto py = [&](double v) { return bottom - static_cast<int>(std::lround(sy.map(v) * (bottom - top))); };

    drawText(image, left, 8, spec.title, kBlack, 2);
    drawText(image, 8, top - 14, spec.y.label, kBlack);
    drawText(image, (left + right - textWidth(spec.x.label)) / 2, spec.height - 14, spec.x.label, kBlack);
    for (double v : ticks(sx)) {
        const int x = px(v);
        image.drawLine(x, top, x, bottom, kGrid);
        image.drawLine(x, bottom, x, bottom + 4, kBlack);
        const std::string t = tickLabel(v);
        drawText(image, x - textWidth(t) / 2, bottom + 8, t, kBlack);
    }
    for (double v : ticks(sy)) {
        const int y = py(v);
        image.drawLine(left, y, right, y, kGrid);
        image.drawLine(left - 4, y, left, y, kBlack);
        const std::string t = tickLabel(v);
        drawText(image, left - 8 - textWidth(t), y - textHeight() / 2, t, kBlack);
    }
    image.drawLine(left, top, left, bottom, kBlack);
    image.drawLine(left, bottom, right, bottom, kBlack);

    for (std::size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& s = spec.series[i];
        const int index = s.colour >= 0 ? s.colour : static_cast<int>(i);
        const Rgb colour = plotColour(index);
        bool havePrevious = false;
        int x0 = 0, y0 = 0;
        for (const auto& p : s.xy) {
            if (!sx.accepts(p.first) || !sy.accepts(p.second)) continue;
            const int x = px(p.first), y = py(p.second);
            if (s.lines && havePrevious) image.drawLine(x0, y0, x, y, colour, 2);
            if (s.markers) drawMarker(image, x, y, static_cast<int>(i), colour);
            x0 = x;
            y0 = y;
            havePrevious = true;
        }
    }

    // Legend, right of the axes.
    if (legendRows > 0) {
        const int w = legendWidth, h = legendRows * 12 + 8, x = spec.width - 8 - w, y = top;
        image.fillRect(x, y, w, h, kWhite);
        image.drawLine(x, y, x + w, y, kBlack);
        image.drawLine(x, y + h, x + w, y + h, kBlack);
        image.drawLine(x, y, x, y + h, kBlack);
        image.drawLine(x + w, y, x + w, y + h, kBlack);
        int row = 0;
        for (std::size_t i = 0; i < spec.series.size(); ++i) {
            const PlotSeries& s = spec.series[i];
            if (s.label.empty()) continue;
            const Rgb colour = plotColour(s.colour >= 0 ? s.colour : static_cast<int>(i));
            const int cy = y + 8 + 12 * row++;
            if (s.lines) image.drawLine(x + 4, cy, x + 22, cy, colour, 2);
            if (s.markers) drawMarker(image, x + 13, cy, static_cast<int>(i), colour);
            drawText(image, x + 28, cy - 3, s.label, kBlack);
        }
    }
    return image;
}

}  // namespace btfracture
