// SPDX-License-Identifier: Zlib
#pragma once
// Wavefront OBJ reader for triangle meshes.
#include <btFracture/core/TriangleMesh.h>

#include <string>

namespace btfracture {

// Reads `v` and `f` records: faces in the forms i, i/t, i/t/n and i//n, 1-based or negative
// (relative) indices, polygons split into triangle fans (logged once). vt, vn, vp, g, o, s,
// usemtl, mtllib and comments are ignored; l and p elements are skipped with a log line.
// Throws btfracture::Error "<path>:<line>: <what was expected>" for malformed records, unknown
// record types and out-of-range indices, and when the file cannot be read. The mesh is NOT
// validated (see readMesh); its name is `path`.
TriangleMesh readObj(const std::string& path);

// The same, from text already in memory; `source` names it in messages.
TriangleMesh parseObj(const std::string& text, const std::string& source);

}  // namespace btfracture
