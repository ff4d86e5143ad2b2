// SPDX-License-Identifier: Zlib
#include <btFracture/io/ObjReader.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/io/PolygonFan.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/TextTokens.h>

#include <sstream>

namespace btfracture {
namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& problem) {
    std::ostringstream msg;
    msg << source << ":" << line << ": " << problem;
    throw Error(msg.str());
}

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

// Index part of an optional "/texture/normal" suffix must be empty or an integer.
bool validSuffix(std::string_view rest) {
    long long ignored;
    size_t start = 0;
    int parts = 0;
    while (start <= rest.size()) {
        size_t slash = rest.find('/', start);
        if (slash == std::string_view::npos) slash = rest.size();
        const std::string_view part = rest.substr(start, slash - start);
        if (!part.empty() && !parseInteger(part, ignored)) return false;
        if (++parts > 2) return false;
        start = slash + 1;
    }
    return true;
}

}  // namespace

TriangleMesh parseObj(const std::string& text, const std::string& source) {
    TriangleMesh mesh;
    mesh.name = source;
    PolygonFan fan(mesh);
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> tokens;
    std::vector<int> corners;
    int skippedElements = 0;
    while (lines.next(line)) {
        splitTokens(line, tokens);
        if (tokens.empty() || tokens[0].front() == '#') continue;
        const std::string_view keyword = tokens[0];
        const int number = lines.lineNumber();
        if (keyword == "v") {
            Eigen::Vector3d p;
            if (tokens.size() < 4)
                fail(source, number, "expected 3 vertex coordinates after 'v', got " + quoted(line));
            for (size_t k = 1; k < tokens.size(); ++k) {
                double value;
                if (!parseDouble(tokens[k], value))
                    fail(source, number,
                         "expected a number for vertex coordinate " + std::to_string(k) + ", got " +
                             quoted(tokens[k]));
                if (k <= 3) p[k - 1] = value;
            }
            mesh.vertices.push_back(p);
        } else if (keyword == "f") {
            if (tokens.size() < 4)
                fail(source, number, "expected at least 3 vertex indices after 'f', got " + quoted(line));
            corners.clear();
            const long long count = static_cast<long long>(mesh.vertices.size());
            for (size_t k = 1; k < tokens.size(); ++k) {
                const std::string_view token = tokens[k];
                const size_t slash = token.find('/');
                long long index;
                if (!parseInteger(token.substr(0, slash), index) ||
                    (slash != std::string_view::npos && !validSuffix(token.substr(slash + 1))))
                    fail(source, number,
                         "expected a face corner of the form i, i/t, i/t/n or i//n, got " + quoted(token));
                const long long resolved = index < 0 ? count + index : index - 1;
                if (index == 0 || resolved < 0 || resolved >= count)
                    fail(source, number,
                         "vertex index " + std::to_string(index) + " out of range (" + std::to_string(count) +
                             " vertices defined so far)");
                corners.push_back(static_cast<int>(resolved));
            }
            fan.add(corners);
        } else if (keyword == "l" || keyword == "p") {
            ++skippedElements;
        } else if (!(keyword == "vt" || keyword == "vn" || keyword == "vp" || keyword == "g" ||
                     keyword == "o" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib")) {
            fail(source, number,
                 "unknown OBJ record " + quoted(keyword) + " (expected v, f, vt, vn, g, o, s, usemtl, ...)");
        }
    }
    fan.report(source);
    if (skippedElements > 0)
        logf(LogLevel::Info, source, ": skipped ", skippedElements,
             " line/point elements (l, p); only faces are read");
    return mesh;
}

TriangleMesh readObj(const std::string& path) {
    return parseObj(readWholeFile(path, "mesh file"), path);
}

}  // namespace btfracture
