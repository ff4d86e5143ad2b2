// SPDX-License-Identifier: Zlib
#include "Report.h"

#include <btFracture/core/Error.h>

#include <cstdio>
#include <fstream>

using namespace btfracture;

namespace accuracy {

namespace {

std::string fmt(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::string orDash(double v, const char* format, double scale = 1.0) {
    return v < 0.0 ? "-" : fmt(format, scale * v);
}

std::ofstream open(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw Error("accuracy: cannot write " + path);
    return out;
}

bool isScene(const RunResult& r) {
    return r.fragments >= 0;
}

}  // namespace

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs) {
    std::ofstream out = open(path);
    out << "case,method,hybrid_threshold,bem_triangles,crack_triangles,steps,bem_setup_s,fracture_s,geometry_"
           "s,"
           "other_engine_s,engine_total_s,first_event_engine_s,events,rigid_body_s,peak_rss_mb,sif_error,"
           "surface_mean_rel,surface_"
           "hausdorff_rel,"
           "fragments,mott_ks,note\n";
    for (const auto& r : runs) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s,%s,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.4f,%.1f,%.5f,%.5f,%.5f,%d,%.4f,",
                      r.caseName.c_str(), r.method.c_str(), r.threshold, r.surfaceTriangles, r.crackTriangles,
                      r.steps, r.bemSeconds, r.fractureSeconds, r.geometrySeconds, r.otherEngineSeconds,
                      r.engineSeconds(), r.firstEventSeconds, r.events, r.rigidSeconds, r.peakMegabytes,
                      r.sifError, r.surfaceMean, r.surfaceHausdorff, r.fragments, r.mottKs);
        out << line << '"' << r.note << "\"\n";
    }
}

void writeStepsCsv(const std::string& path, const std::vector<RunResult>& runs) {
    std::ofstream out = open(path);
    out << "case,method,step,elements,active_front_m,front_nodes,step_s,estimated,mean_KI,mean_Keff\n";
    for (const auto& r : runs)
        for (std::size_t i = 0; i < r.stepSamples.size(); ++i) {
            const StepSample& s = r.stepSamples[i];
            char line[320];
            std::snprintf(line, sizeof line, "%s,%s,%zu,%d,%.5f,%d,%.5f,%d,%.6g,%.6g\n", r.caseName.c_str(),
                          r.method.c_str(), i, s.elements, s.frontLength, s.frontNodes, s.seconds,
                          s.estimated ? 1 : 0, s.meanKI, s.meanKeff);
            out << line;
        }
}

void writeMarkdownTable(const std::string& path, const std::vector<RunResult>& runs) {
    std::ofstream out = open(path);
    out << "| case | method | BEM tris | crack tris | steps / events | fracture s | engine s | rigid s | "
           "peak MB | "
           "SIF err % | "
           "surface mean / Hausdorff % | fragments | Mott KS |\n"
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<std::string> failures;
    for (const auto& r : runs) {
        const std::string method =
            r.threshold > 0 ? r.method + " (" + std::to_string(r.threshold) + ")" : r.method;
        if (r.failed()) {  // no result: the reason goes below the table
            out << "| " << r.caseName << " | " << method << " | - | - | - | - | - | - | "
                << fmt("%.0f", r.peakMegabytes) << " | - | - | - | - |\n";
            failures.push_back(r.caseName + " / " + method + ": " + r.note);
            continue;
        }
        const std::string surface = r.surfaceMean < 0.0 ? "-"
                                                        : fmt("%.2f", 100 * r.surfaceMean) + " / " +
                                                              fmt("%.1f", 100 * r.surfaceHausdorff);
        out << "| " << r.caseName << " | " << method << " | " << r.surfaceTriangles << " | "
            << r.crackTriangles << " | " << std::to_string(isScene(r) ? r.events : r.steps) << " | "
            << fmt("%.3f", r.fractureSeconds) << " | " << (isScene(r) ? fmt("%.2f", r.engineSeconds()) : "-")
            << " | " << (isScene(r) ? fmt("%.2f", r.rigidSeconds) : "-") << " | "
            << fmt("%.0f", r.peakMegabytes) << " | " << orDash(r.sifError, "%.1f", 100.0) << " | " << surface
            << " | " << (r.fragments < 0 ? std::string("-") : std::to_string(r.fragments)) << " | "
            << orDash(r.mottKs, "%.2f") << " |\n";
    }
    if (!failures.empty()) out << "\n";
    for (const std::string& f : failures) out << "- " << f << "\n";
}

}  // namespace accuracy
