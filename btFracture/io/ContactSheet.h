// SPDX-License-Identifier: Zlib
#pragma once
// A contact sheet: several frames reduced and laid out in a grid in one image.
#include <btFracture/io/Image.h>

#include <string>
#include <vector>

namespace btfracture {

// Which of `count` frames a sheet of at most `cells` shows: all when they fit, otherwise `cells`
// evenly spaced indices from the first to the last frame (ascending, no repeats).
std::vector<size_t> contactSheetSelection(size_t count, size_t cells);

// Lays `frames` (all of one size) out row by row in `columns` columns, each reduced to
// `thumbnailWidth` pixels wide (keeping the aspect ratio; frames narrower than that keep their
// size), with a 4-pixel gap and labels[i] (if given) under frame i. Throws btfracture::Error for
// no frames, frames of different sizes, or labels that do not match the frames in number.
Image contactSheet(const std::vector<Image>& frames, const std::vector<std::string>& labels, int columns,
                   int thumbnailWidth);

}  // namespace btfracture
