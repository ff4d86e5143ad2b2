// SPDX-License-Identifier: Zlib
// Charts (io/Plot.h): series land where their data say on linear and log axes, in their colour,
// non-positive values are left out on log axes, and the output is deterministic.
#include <btFracture/io/BitmapFont.h>
#include <btFracture/io/Plot.h>

#include <gtest/gtest.h>

using namespace btfracture;

namespace {

int countColour(const Image& image, Rgb colour, int x0, int x1) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = x0; x < x1; ++x) n += image.at(x, y) == colour;
    return n;
}

}  // namespace

TEST(Plot, DrawsSeriesInTheirColourOnLogAxes) {
    PlotSpec spec;
    spec.title = "test";
    spec.x = {"x", true};
    spec.y = {"y", true};
    PlotSeries rising;
    rising.label = "rising";
    rising.xy = {{1, 1}, {10, 10}, {100, 100}};
    PlotSeries ignored;
    ignored.label = "ignored";
    ignored.colour = 2;
    ignored.xy = {{-1, 5}, {0, 5}};  // nothing drawable on a log axis
    spec.series = {rising, ignored};
    const Image image = plotChart(spec);
    ASSERT_EQ(image.width(), spec.width);
    // The rising line crosses the whole plot area: its colour appears in the left and the right
    // half; the ignored series only in its legend swatch.
    const Rgb blue = plotColour(0), green = plotColour(2);
    EXPECT_GT(countColour(image, blue, 80, spec.width / 2), 50);
    EXPECT_GT(countColour(image, blue, spec.width / 2, spec.width - 200), 50);
    EXPECT_LT(countColour(image, green, 0, spec.width - 200), 10);
    // Log scale: the point (10, 10) sits in the middle of both decades' span. The axes end where
    // the legend (right of them: widest label + 34 pixels, 8 apart) begins.
    const int right = spec.width - 16 - (textWidth("ignored") + 34 + 8);
    bool middle = false;
    for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx)
            middle |= image.at((72 + right) / 2 + dx, (40 + spec.height - 44) / 2 + dy) == blue;
    EXPECT_TRUE(middle);
    const Image again = plotChart(spec);
    EXPECT_EQ(image.pixels(), again.pixels());
}

TEST(Plot, EmptyChartStillHasAxes) {
    PlotSpec spec;
    spec.width = 200;
    spec.height = 150;
    const Image image = plotChart(spec);
    EXPECT_EQ(image.at(72, 150 - 44), (Rgb{0, 0, 0}));  // the axes' corner
}
