// SPDX-License-Identifier: Zlib
#pragma once
// Loads a closed triangle mesh from a file and validates it.
#include <btFracture/core/TriangleMesh.h>

#include <string>

namespace btfracture {

// Reads `path` by its extension (.obj or .ply, any case; see ObjReader.h, PlyReader.h), then
// checks it with requireClosedSolid (core/MeshCheck.h): open boundaries, non-manifold edges or
// vertices, inconsistent orientation, degenerate triangles, non-finite coordinates and
// self-intersections are errors that name the file and give the counts; an inside-out mesh is
// flipped with a warning. The mesh's name is `path`. Several closed parts in one file are fine.
TriangleMesh readMesh(const std::string& path);

}  // namespace btfracture
