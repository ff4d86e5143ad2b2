// SPDX-License-Identifier: Zlib
#include <btFracture/io/ContactSheet.h>

#include <btFracture/core/Error.h>
#include <btFracture/io/BitmapFont.h>

#include <algorithm>
#include <cmath>

namespace btfracture {

std::vector<size_t> contactSheetSelection(size_t count, size_t cells) {
    std::vector<size_t> chosen;
    if (count == 0 || cells == 0) return chosen;
    if (count <= cells || cells == 1) {
        for (size_t i = 0; i < std::min(count, cells); ++i) chosen.push_back(i);
        return chosen;
    }
    for (size_t k = 0; k < cells; ++k) {
        // Rounded k (count - 1) / (cells - 1): strictly increasing since count > cells.
        chosen.push_back((2 * k * (count - 1) + (cells - 1)) / (2 * (cells - 1)));
    }
    return chosen;
}

Image contactSheet(const std::vector<Image>& frames, const std::vector<std::string>& labels, int columns,
                   int thumbnailWidth) {
    if (frames.empty()) throw Error("contactSheet: no frames");
    if (!labels.empty() && labels.size() != frames.size())
        throw Error("contactSheet: " + std::to_string(labels.size()) + " labels for " +
                    std::to_string(frames.size()) + " frames");
    if (columns < 1 || thumbnailWidth < 1)
        throw Error("contactSheet: columns and thumbnail width must be positive");
    const int width = frames[0].width(), height = frames[0].height();
    for (const Image& f : frames)
        if (f.width() != width || f.height() != height)
            throw Error("contactSheet: frames differ in size (" + std::to_string(width) + " x " +
                        std::to_string(height) + " and " + std::to_string(f.width()) + " x " +
                        std::to_string(f.height()) + ")");
    const int cellWidth = std::min(width, thumbnailWidth);
    const int cellHeight =
        std::max(1, static_cast<int>(std::lround(static_cast<double>(height) * cellWidth / width)));
    const int gap = 4, labelHeight = labels.empty() ? 0 : textHeight() + 2;
    const int count = static_cast<int>(frames.size());
    const int cols = std::min(columns, count), rows = (count + cols - 1) / cols;
    Image sheet(gap + cols * (cellWidth + gap), gap + rows * (cellHeight + labelHeight + gap),
                Rgb{255, 255, 255});
    for (int k = 0; k < count; ++k) {
        const int x = gap + (k % cols) * (cellWidth + gap);
        const int y = gap + (k / cols) * (cellHeight + labelHeight + gap);
        sheet.blit(frames[k].resized(cellWidth, cellHeight), x, y);
        if (!labels.empty()) drawText(sheet, x, y + cellHeight + 2, labels[k], Rgb{40, 40, 48});
    }
    return sheet;
}

}  // namespace btfracture
