// SPDX-License-Identifier: Zlib
#include <btFracture/io/MottHistogram.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>
#include <btFracture/io/BitmapFont.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace btfracture {

double mottSurvival(double volume, double meanVolume) {
    if (!(meanVolume > 0.0) || !std::isfinite(meanVolume))
        throw Error("mottSurvival: the mean fragment volume must be positive and finite, got " +
                    std::to_string(meanVolume));
    if (volume <= 0.0) return 1.0;
    const double zeta = 6.0 / meanVolume;
    return pmath::exp(-std::cbrt(zeta * volume));
}

MottComparison compareWithMott(std::vector<double> volumes, int binsPerDecade) {
    if (volumes.empty()) throw Error("compareWithMott: no fragment volumes");
    if (binsPerDecade < 1 || binsPerDecade > 20)
        throw Error("compareWithMott: bins per decade must lie in [1, 20], got " +
                    std::to_string(binsPerDecade));
    for (double v : volumes)
        if (!(v > 0.0) || !std::isfinite(v))
            throw Error("compareWithMott: fragment volumes must be positive and finite, got " +
                        std::to_string(v));
    std::sort(volumes.begin(), volumes.end());
    MottComparison c;
    double sum = 0.0;
    for (double v : volumes) sum += v;
    c.mean = sum / static_cast<double>(volumes.size());
    const double n = static_cast<double>(volumes.size());
    for (size_t i = 0; i < volumes.size(); ++i) {
        // The fragments' survival steps from (n - i) / n down to (n - i - 1) / n at volumes[i].
        const double p = mottSurvival(volumes[i], c.mean);
        c.ksDistance = std::max({c.ksDistance, std::abs((n - i) / n - p), std::abs((n - i - 1) / n - p)});
    }
    const int first = static_cast<int>(std::floor(pmath::log10(volumes.front()) * binsPerDecade));
    const int last = static_cast<int>(std::floor(pmath::log10(volumes.back()) * binsPerDecade));
    size_t next = 0;
    for (int k = first; k <= last; ++k) {
        MottBin bin;
        bin.lower = pmath::pow(10.0, static_cast<double>(k) / binsPerDecade);
        bin.upper = pmath::pow(10.0, static_cast<double>(k + 1) / binsPerDecade);
        // Bin edges from pow() may round differently from log10(): the last bin takes the rest.
        while (next < volumes.size() && (volumes[next] < bin.upper || k == last)) {
            ++bin.count;
            ++next;
        }
        bin.expected = n * (mottSurvival(bin.lower, c.mean) - mottSurvival(bin.upper, c.mean));
        c.bins.push_back(bin);
    }
    c.volumes = std::move(volumes);
    return c;
}

void writeMottCsv(const std::string& path, const MottComparison& c) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot create histogram file '" + path + "'");
    out << "bin_lower,bin_upper,count,mott_expected,survival_fragments,survival_mott\n";
    const double n = static_cast<double>(c.volumes.size());
    for (const MottBin& b : c.bins) {
        const double atLeast = static_cast<double>(
            c.volumes.end() - std::lower_bound(c.volumes.begin(), c.volumes.end(), b.lower));
        char line[256];
        std::snprintf(line, sizeof line, "%.9g,%.9g,%d,%.9g,%.9g,%.9g\n", b.lower, b.upper, b.count,
                      b.expected, atLeast / n, mottSurvival(b.lower, c.mean));
        out << line;
    }
    out.close();
    if (out.fail()) throw Error("writing histogram file '" + path + "' failed");
}

namespace {

const Rgb kInk{40, 40, 48}, kGrid{222, 224, 228}, kBar{150, 170, 200}, kMott{200, 40, 40},
    kFragments{30, 70, 170};

// A plot panel: data coordinates (x = log10 relative volume) to pixels.
struct Panel {
    int left, top, width, height;
    double xMin, xMax, yMin, yMax;
    int px(double x) const {
        return left + static_cast<int>(std::lround((x - xMin) / (xMax - xMin) * width));
    }
    int py(double y) const {
        return top + height - static_cast<int>(std::lround((y - yMin) / (yMax - yMin) * height));
    }
};

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

void drawFrame(Image& image, const Panel& p, const std::string& yLabel, const std::string& title) {
    for (int d = static_cast<int>(std::ceil(p.xMin)); d <= static_cast<int>(std::floor(p.xMax)); ++d) {
        image.drawLine(p.px(d), p.top, p.px(d), p.top + p.height, kGrid);
        const std::string label = "1E" + std::to_string(d);
        drawText(image, p.px(d) - textWidth(label) / 2, p.top + p.height + 4, label, kInk);
    }
    for (int k = 0; k <= 4; ++k) {
        const double y = p.yMin + (p.yMax - p.yMin) * k / 4.0;
        image.drawLine(p.left, p.py(y), p.left + p.width, p.py(y), kGrid);
        const std::string label = shortNumber(std::round(y * 100.0) / 100.0);
        drawText(image, p.left - textWidth(label) - 4, p.py(y) - 3, label, kInk);
    }
    image.drawLine(p.left, p.top, p.left, p.top + p.height, kInk);
    image.drawLine(p.left, p.top + p.height, p.left + p.width, p.top + p.height, kInk);
    drawText(image, p.left, p.top - 12, title + "  (" + yLabel + ")", kInk);
    drawText(image, p.left + p.width / 2 - textWidth("RELATIVE VOLUME V/V0") / 2, p.top + p.height + 16,
             "RELATIVE VOLUME V/V0", kInk);
}

}  // namespace

Image plotMott(const MottComparison& c, int width, int height) {
    if (c.volumes.empty() || c.bins.empty()) throw Error("plotMott: no fragments to plot");
    Image image(width, height, Rgb{255, 255, 255});
    const double xMin = pmath::log10(c.bins.front().lower), xMax = pmath::log10(c.bins.back().upper);
    const int panelWidth = (width - 3 * 60) / 2, panelHeight = height - 90;
    int maxCount = 1;
    double maxExpected = 0.0;
    for (const MottBin& b : c.bins) {
        maxCount = std::max(maxCount, b.count);
        maxExpected = std::max(maxExpected, b.expected);
    }
    // Four grid steps of whole counts.
    const double countTop = 4.0 * std::ceil(std::max<double>(maxCount, maxExpected) * 1.1 / 4.0);
    const Panel histogram{60, 40, panelWidth, panelHeight, xMin, xMax, 0.0, countTop};
    drawFrame(image, histogram, "COUNT", "FRAGMENTS PER BIN");
    for (const MottBin& b : c.bins) {
        const int x0 = histogram.px(pmath::log10(b.lower)) + 1, x1 = histogram.px(pmath::log10(b.upper)) - 1;
        const int y = histogram.py(b.count);
        image.fillRect(x0, y, x1 - x0 + 1, histogram.py(0) - y, kBar);
        const int ye = histogram.py(b.expected);
        image.drawLine(x0, ye, x1, ye, kMott, 3);
    }

    const Panel survival{2 * 60 + panelWidth, 40, panelWidth, panelHeight, xMin, xMax, 0.0, 1.0};
    drawFrame(image, survival, "P(>=V)", "SURVIVAL");
    // Mott's curve, sampled per pixel column.
    int lastX = survival.left, lastY = survival.py(mottSurvival(pmath::pow(10.0, xMin), c.mean));
    for (int x = survival.left + 1; x <= survival.left + survival.width; ++x) {
        const double v = pmath::pow(10.0, xMin + (xMax - xMin) * (x - survival.left) / survival.width);
        const int y = survival.py(mottSurvival(v, c.mean));
        image.drawLine(lastX, lastY, x, y, kMott, 2);
        lastX = x;
        lastY = y;
    }
    // The fragments' survival function: a step down at each volume.
    const double n = static_cast<double>(c.volumes.size());
    int x0 = survival.left, y0 = survival.py(1.0);
    for (size_t i = 0; i < c.volumes.size(); ++i) {
        const int x = survival.px(pmath::log10(c.volumes[i]));
        image.drawLine(x0, y0, x, y0, kFragments, 2);
        const int y = survival.py((n - i - 1) / n);
        image.drawLine(x, y0, x, y, kFragments, 2);
        x0 = x;
        y0 = y;
    }
    image.drawLine(x0, y0, survival.left + survival.width, y0, kFragments, 2);

    char legend[160];
    std::snprintf(legend, sizeof legend, "FRAGMENTS: %zu  MEAN V/V0 %.3g  KS DISTANCE %.3f", c.volumes.size(),
                  c.mean, c.ksDistance);
    drawText(image, 60, 8, legend, kFragments);
    drawText(image, 60 + textWidth(legend) + 24, 8, "MOTT: P = EXP(-(ZETA V)^(1/3)), ZETA = 6/MEAN", kMott);
    return image;
}

}  // namespace btfracture
