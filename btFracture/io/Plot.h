// SPDX-License-Identifier: Zlib
#pragma once
// Minimal x-y charts as PNG-ready images: axes with ticks, linear or logarithmic scales, labelled
// series (lines and/or markers) and a legend; used by the benchmarks' reports.
#include <btFracture/io/Image.h>

#include <string>
#include <utility>
#include <vector>

namespace btfracture {

struct PlotSeries {
    std::string label;                          // legend text; empty: not in the legend
    std::vector<std::pair<double, double>> xy;  // points in data units, drawn in this order
    bool lines = true;                          // join consecutive points
    bool markers = true;                        // a marker at each point
    int colour = -1;                            // palette index; -1: the series' position
};

struct PlotAxis {
    std::string label;
    bool logarithmic = false;  // non-positive values are left out on a log axis
};

struct PlotSpec {
    std::string title;
    PlotAxis x, y;
    std::vector<PlotSeries> series;
    int width = 720, height = 480;  // [pixels]
};

// Colour `index` of a fixed palette of 8 distinguishable colours (repeats after 8).
Rgb plotColour(int index);

// Draws the chart, the legend right of the axes. Points with a non-finite coordinate are skipped; an empty
// chart still gets its axes (range [0, 1], or [1, 10] on log axes).
Image plotChart(const PlotSpec& spec);

}  // namespace btfracture
