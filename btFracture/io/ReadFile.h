// SPDX-License-Identifier: Zlib
#pragma once
// Whole-file reading shared by the mesh and scene readers.
#include <string>

namespace btfracture {

// The file's bytes. Throws btfracture::Error "cannot open <what> '<path>': <reason>" when the file
// is missing or unreadable.
std::string readWholeFile(const std::string& path, const std::string& what);

}  // namespace btfracture
