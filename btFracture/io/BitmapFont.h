// SPDX-License-Identifier: Zlib
#pragma once
// A 5 x 7 pixel bitmap font for labels on preview images and plots: digits, letters (lower case
// drawn as upper case) and common punctuation; other characters are drawn as '?'.
#include <btFracture/io/Image.h>

#include <string>

namespace btfracture {

// Each glyph cell is 6 x 8 pixels (one column and one row of spacing) times `scale`.
int textWidth(const std::string& text, int scale = 1);
int textHeight(int scale = 1);

// Draws `text` with the top-left corner of its first cell at (x, y), clipped to the image.
void drawText(Image& image, int x, int y, const std::string& text, Rgb colour, int scale = 1);

}  // namespace btfracture
