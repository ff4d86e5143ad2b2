// SPDX-License-Identifier: Zlib
#pragma once
// Whole files that appear complete or not at all: written to `path`.tmp in the same folder, then
// renamed over `path` (rename is atomic within a file system). A reader, or a process that finds
// the folder after a crash, never sees half a file under `path`.
#include <string>

namespace btfracture {

// Throws btfracture::Error naming the file when it cannot be written or renamed.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace btfracture
