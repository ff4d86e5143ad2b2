// SPDX-License-Identifier: Zlib
#pragma once
// Wavefront OBJ output: one file holding several named objects, or a single mesh.
#include <btFracture/core/TriangleMesh.h>

#include <fstream>
#include <string>
#include <vector>

namespace btfracture {

class ObjWriter {
public:
    // Creates (truncates) `path`. Coordinates are written with `significantDigits` significant
    // digits: 9 keeps single-precision detail in small files, 17 round-trips doubles exactly.
    // Throws btfracture::Error naming the path when the file cannot be created.
    explicit ObjWriter(std::string path, int significantDigits = 9);
    ObjWriter(const ObjWriter&) = delete;
    ObjWriter& operator=(const ObjWriter&) = delete;
    ~ObjWriter();

    // Appends "o <name>" followed by the mesh's vertices and faces (indices continue across
    // objects). Names must be non-empty without whitespace, or an Error is thrown.
    void addObject(const std::string& name, const TriangleMesh& mesh);
    // The same with materials: "mtllib <materialLibrary>" (once per file), then the faces
    // grouped under "usemtl outside" and "usemtl interior" (crackFaces[t]: triangle t is a crack
    // face; one flag per triangle, or empty for none).
    void addObject(const std::string& name, const TriangleMesh& mesh, const std::vector<bool>& crackFaces,
                   const std::string& materialLibrary);
    // Flushes and closes; throws Error naming the path when writing failed (disk full, ...).
    // Called by the destructor too, which then only logs failures.
    void close();

private:
    void writeNumber(double value);
    void writeVertices(const std::string& name, const TriangleMesh& mesh);
    void writeFace(const std::array<int, 3>& t);

    std::string path_;
    std::ofstream out_;
    int significantDigits_;
    long long verticesWritten_ = 0;  // before the current object
    std::string materialLibrary_;
    bool closed_ = false;
};

// One mesh as one object named after mesh.name's file stem (or "mesh").
void writeObj(const std::string& path, const TriangleMesh& mesh, int significantDigits = 9);

// The material library of ObjWriter's materials (outside, interior: CrackFaces.h).
void writeObjMaterials(const std::string& path);

}  // namespace btfracture
