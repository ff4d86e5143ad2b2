// SPDX-License-Identifier: Zlib
#pragma once
// SHA-256 (FIPS 180-4) of bytes and files, as lowercase hex: run.json names the exact inputs of
// a run with it.
#include <string>

namespace btfracture {

std::string sha256Hex(const std::string& bytes);
// Throws btfracture::Error naming the file when it cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace btfracture
