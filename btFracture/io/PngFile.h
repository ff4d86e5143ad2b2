// SPDX-License-Identifier: Zlib
#pragma once
// PNG files through libpng (8-bit RGB, no time stamp or other varying chunks, so the same image
// always gives the same bytes).
#include <btFracture/io/Image.h>

#include <string>

namespace btfracture {

// Writes `image` to `path` (created or truncated). Throws btfracture::Error naming the path and
// libpng's reason when the file cannot be written.
void writePng(const std::string& path, const Image& image);

// Reads an 8-bit or 16-bit, grey, RGB or palette PNG as RGB (alpha composited on black).
// Throws btfracture::Error naming the path and libpng's reason for missing or malformed files.
Image readPng(const std::string& path);

}  // namespace btfracture
