// SPDX-License-Identifier: Zlib
#include "RunResult.h"

#include <btFracture/core/Error.h>

#include <cstdio>
#include <sstream>

namespace accuracy {

namespace {

std::string noSpaces(std::string s) {
    for (char& c : s)
        if (c == ' ' || c == '\n' || c == '\t') c = '_';
    return s.empty() ? "-" : s;
}

std::string restore(const std::string& s) {
    return s == "-" ? std::string() : s;
}

}  // namespace

// Line-oriented: "R" with the scalars, then "S" per step, "F" per fragment volume, "V"/"T" for
// the surface mesh. Doubles in %.17g so that nothing is lost on the way.
std::string serialize(const RunResult& r) {
    std::ostringstream out;
    out.precision(17);
    out << "R " << noSpaces(r.caseName) << ' ' << noSpaces(r.method) << ' ' << r.threshold << ' '
        << r.surfaceTriangles << ' ' << r.bodySize << ' ' << r.crackTriangles << ' ' << r.steps << ' '
        << r.bemSeconds << ' ' << r.fractureSeconds << ' ' << r.geometrySeconds << ' ' << r.otherEngineSeconds
        << ' ' << r.rigidSeconds << ' ' << r.peakMegabytes << ' ' << r.sifError << ' ' << r.fragments << ' '
        << r.mottKs << ' ' << r.events << ' ' << r.firstEventSeconds << ' ' << noSpaces(r.note) << '\n';
    for (const auto& s : r.stepSamples)
        out << "S " << s.elements << ' ' << s.frontLength << ' ' << s.frontNodes << ' ' << s.seconds << ' '
            << (s.estimated ? 1 : 0) << ' ' << s.meanKI << ' ' << s.meanKeff << '\n';
    for (double v : r.fragmentVolumes) out << "F " << v << '\n';
    for (const auto& v : r.surface.vertices) out << "V " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : r.surface.triangles) out << "T " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return out.str();
}

RunResult deserialize(const std::string& text) {
    RunResult r;
    std::istringstream in(text);
    std::string line;
    bool haveHeader = false;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::string tag;
        l >> tag;
        if (tag == "R") {
            std::string name, method, note;
            l >> name >> method >> r.threshold >> r.surfaceTriangles >> r.bodySize >> r.crackTriangles >>
                r.steps >> r.bemSeconds >> r.fractureSeconds >> r.geometrySeconds >> r.otherEngineSeconds >>
                r.rigidSeconds >> r.peakMegabytes >> r.sifError >> r.fragments >> r.mottKs >> r.events >>
                r.firstEventSeconds >> note;
            r.caseName = restore(name);
            r.method = restore(method);
            r.note = restore(note);
            for (char& c : r.note)
                if (c == '_') c = ' ';
            haveHeader = true;
        } else if (tag == "S") {
            StepSample s;
            int est = 0;
            l >> s.elements >> s.frontLength >> s.frontNodes >> s.seconds >> est >> s.meanKI >> s.meanKeff;
            s.estimated = est != 0;
            r.stepSamples.push_back(s);
        } else if (tag == "F") {
            double v = 0.0;
            l >> v;
            r.fragmentVolumes.push_back(v);
        } else if (tag == "V") {
            double x = 0, y = 0, z = 0;
            l >> x >> y >> z;
            r.surface.vertices.emplace_back(x, y, z);
        } else if (tag == "T") {
            std::array<int, 3> t{};
            l >> t[0] >> t[1] >> t[2];
            r.surface.triangles.push_back(t);
        }
        if (!l && !tag.empty()) throw btfracture::Error("accuracy: malformed run line '" + line + "'");
    }
    if (!haveHeader) throw btfracture::Error("accuracy: run produced no result (crashed?)");
    return r;
}

}  // namespace accuracy
