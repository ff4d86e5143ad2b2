// SPDX-License-Identifier: Zlib
#pragma once
// Stanford PLY reader for triangle meshes.
#include <btFracture/core/TriangleMesh.h>

#include <string>

namespace btfracture {

// Formats ascii 1.0, binary_little_endian 1.0 and binary_big_endian 1.0. Reads the `vertex`
// element's x, y, z (any numeric type, usually float or double) and the `face` element's list
// property vertex_indices (or vertex_index) with an integer count type (uchar, int, ...) and
// integer items; every other property and element is skipped. Polygons become triangle fans
// (logged once). Throws btfracture::Error naming the file and the header line or the element
// and item ("<path>: face 12: vertex index 99 out of range (8 vertices)"). The mesh is NOT
// validated (see readMesh); its name is `path`.
TriangleMesh readPly(const std::string& path);

// The same, from bytes already in memory; `source` names it in messages.
TriangleMesh parsePly(const std::string& bytes, const std::string& source);

}  // namespace btfracture
