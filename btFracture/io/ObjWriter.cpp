// SPDX-License-Identifier: Zlib
#include <btFracture/io/ObjWriter.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/io/CrackFaces.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>

namespace btfracture {

ObjWriter::ObjWriter(std::string path, int significantDigits)
    : path_(std::move(path)),
      out_(path_, std::ios::binary | std::ios::trunc),
      significantDigits_(significantDigits) {
    if (!out_) throw Error("cannot create OBJ file '" + path_ + "': " + std::strerror(errno));
    if (significantDigits < 1 || significantDigits > 17)
        throw Error("OBJ file '" + path_ + "': significant digits must be in [1, 17], got " +
                    std::to_string(significantDigits));
}

ObjWriter::~ObjWriter() {
    try {
        close();
    } catch (const Error& e) {
        log(LogLevel::Error, e.what());
    }
}

void ObjWriter::writeNumber(double value) {
    char buffer[32];
    const auto result =
        std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, significantDigits_);
    out_.write(buffer, result.ptr - buffer);
}

void ObjWriter::writeVertices(const std::string& name, const TriangleMesh& mesh) {
    if (closed_) throw Error("OBJ file '" + path_ + "': addObject after close");
    if (name.empty() ||
        std::any_of(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }))
        throw Error("OBJ file '" + path_ + "': object name '" + name +
                    "' must be non-empty without whitespace");
    out_ << "o " << name << '\n';
    for (const auto& v : mesh.vertices) {
        out_ << "v ";
        writeNumber(v.x());
        out_ << ' ';
        writeNumber(v.y());
        out_ << ' ';
        writeNumber(v.z());
        out_ << '\n';
    }
}

void ObjWriter::writeFace(const std::array<int, 3>& t) {
    out_ << "f " << t[0] + 1 + verticesWritten_ << ' ' << t[1] + 1 + verticesWritten_ << ' '
         << t[2] + 1 + verticesWritten_ << '\n';
}

void ObjWriter::addObject(const std::string& name, const TriangleMesh& mesh) {
    writeVertices(name, mesh);
    for (const auto& t : mesh.triangles) writeFace(t);
    verticesWritten_ += static_cast<long long>(mesh.vertices.size());
}

void ObjWriter::addObject(const std::string& name, const TriangleMesh& mesh,
                          const std::vector<bool>& crackFaces, const std::string& materialLibrary) {
    if (!crackFaces.empty() && crackFaces.size() != mesh.triangles.size())
        throw Error("OBJ file '" + path_ + "': object '" + name + "' needs one crack flag per triangle");
    if (materialLibrary_.empty()) {
        out_ << "mtllib " << materialLibrary << '\n';
        materialLibrary_ = materialLibrary;
    } else if (materialLibrary != materialLibrary_) {
        throw Error("OBJ file '" + path_ + "': one material library per file");
    }
    writeVertices(name, mesh);
    for (const bool interior : {false, true}) {
        const SurfaceMaterial& material = interior ? kInteriorMaterial : kOutsideMaterial;
        bool named = false;
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            if ((!crackFaces.empty() && crackFaces[t]) != interior) continue;
            if (!named) out_ << "usemtl " << material.name << '\n';
            named = true;
            writeFace(mesh.triangles[t]);
        }
    }
    verticesWritten_ += static_cast<long long>(mesh.vertices.size());
}

void ObjWriter::close() {
    if (closed_) return;
    closed_ = true;
    out_.close();
    if (out_.fail()) throw Error("writing OBJ file '" + path_ + "' failed: " + std::strerror(errno));
}

void writeObj(const std::string& path, const TriangleMesh& mesh, int significantDigits) {
    std::string name = mesh.name.substr(mesh.name.find_last_of('/') + 1);
    name = name.substr(0, name.find_last_of('.'));
    std::replace_if(
        name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }, '_');
    ObjWriter writer(path, significantDigits);
    writer.addObject(name.empty() ? "mesh" : name, mesh);
    writer.close();
}

void writeObjMaterials(const std::string& path) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot create material library '" + path + "': " + std::strerror(errno));
    for (const SurfaceMaterial& m : {kOutsideMaterial, kInteriorMaterial})
        out << "newmtl " << m.name << "\nKd " << m.rgb[0] << ' ' << m.rgb[1] << ' ' << m.rgb[2] << "\n\n";
    out.close();
    if (out.fail()) throw Error("writing material library '" + path + "' failed");
}

}  // namespace btfracture
