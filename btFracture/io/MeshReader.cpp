// SPDX-License-Identifier: Zlib
#include <btFracture/io/MeshReader.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/io/ObjReader.h>
#include <btFracture/io/PlyReader.h>

#include <algorithm>
#include <cctype>

namespace btfracture {

TriangleMesh readMesh(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    std::string extension =
        dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    TriangleMesh mesh;
    if (extension == ".obj") {
        mesh = readObj(path);
    } else if (extension == ".ply") {
        mesh = readPly(path);
    } else {
        throw Error("cannot read mesh file '" + path + "': unsupported extension '" + extension +
                    "' (expected .obj or .ply)");
    }
    requireClosedSolid(mesh);
    logf(LogLevel::Debug, path, ": ", mesh.vertices.size(), " vertices, ", mesh.triangles.size(),
         " triangles");
    return mesh;
}

}  // namespace btfracture
