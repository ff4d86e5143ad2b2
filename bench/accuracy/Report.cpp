// SPDX-License-Identifier: Zlib
#include "Report.h"

#include <btFracture/core/Error.h>
#include <btFracture/io/Plot.h>
#include <btFracture/io/PngFile.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>

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

int maxElements(const RunResult& r) {
    return r.surfaceTriangles + r.crackTriangles;
}

bool isScene(const RunResult& r) {
    return r.fragments >= 0;
}

// The error a Pareto chart shows: SIF error for the solver-level cases, mean surface distance
// (% of the body size) for the scenes (they have no SIF reference) [%].
double paretoError(const RunResult& r) {
    if (isScene(r)) return r.surfaceMean < 0.0 ? -1.0 : 100.0 * r.surfaceMean;
    return r.sifError < 0.0 ? -1.0 : 100.0 * r.sifError;
}

double paretoTime(const RunResult& r) {
    return isScene(r) ? r.engineSeconds() : r.fractureSeconds;
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
    for (const auto& r : runs) {
        const std::string method =
            r.threshold > 0 ? r.method + " (" + std::to_string(r.threshold) + ")" : r.method;
        const std::string surface = r.surfaceMean < 0.0 ? "-"
                                                        : fmt("%.2f", 100 * r.surfaceMean) + " / " +
                                                              fmt("%.1f", 100 * r.surfaceHausdorff);
        out << "| " << r.caseName << " | " << method << " | " << r.surfaceTriangles << " | "
            << r.crackTriangles << " | " << std::to_string(isScene(r) ? r.events : r.steps) << " | "
            << fmt("%.3f", r.fractureSeconds) << " | " << (isScene(r) ? fmt("%.2f", r.engineSeconds()) : "-")
            << " | " << (isScene(r) ? fmt("%.2f", r.rigidSeconds) : "-") << " | "
            << fmt("%.0f", r.peakMegabytes) << " | " << orDash(r.sifError, "%.1f", 100.0) << " | " << surface
            << " | " << (r.fragments < 0 ? std::string("-") : std::to_string(r.fragments)) << " | "
            << orDash(r.mottKs, "%.2f") << " |" << (r.note.empty() ? "" : " ") << "\n";
    }
}

std::vector<std::string> writeCharts(const std::string& directory, const std::vector<RunResult>& runs) {
    std::vector<std::string> written;
    auto save = [&](const std::string& name, const PlotSpec& spec) {
        writePng(directory + "/" + name, plotChart(spec));
        written.push_back(name);
    };
    // Pareto chart per case: one point per method.
    std::vector<std::string> cases;
    for (const auto& r : runs)
        if (cases.empty() || cases.back() != r.caseName) cases.push_back(r.caseName);
    for (const auto& c : cases) {
        PlotSpec spec;
        spec.width = 480;
        spec.height = 320;
        spec.title = c;
        spec.x = {"time in fracture [s]", true};
        bool scene = false;
        for (const auto& r : runs) {
            if (r.caseName != c) continue;
            scene = isScene(r);
            const double e = paretoError(r);
            if (e < 0.0) continue;
            PlotSeries s;
            s.label = r.method;
            s.xy = {{paretoTime(r), e}};
            s.lines = false;
            spec.series.push_back(s);
        }
        spec.y = {scene ? "fracture surface distance to FULL [% of size]" : "SIF error [%]", false};
        save("pareto_" + c + ".png", spec);
    }
    // Step time against elements and against active front length: FULL and EST steps of the
    // growth runs (HYBRID steps are one or the other).
    PlotSpec byElements, byFront;
    byElements.title = "time per propagation step vs BEM elements";
    byElements.x = {"BEM elements (surface + crack triangles)", true};
    byElements.y = {"step time [s]", true};
    byFront.title = "time per propagation step vs active front length";
    byFront.x = {"active front length [m]", false};
    byFront.y = {"step time [s]", false};
    int colour = 0, estColour = 0;
    for (const auto& r : runs) {
        if (r.stepSamples.size() < 3 || (r.method != "FULL" && r.method != "EST")) continue;
        PlotSeries e, f;
        e.label = f.label = r.caseName + " " + r.method;
        e.colour = colour++;
        if (r.method == "EST") f.colour = estColour++;
        for (const auto& s : r.stepSamples) {
            if (s.seconds < 1e-3) continue;  // the closing step in which every node arrested: no work
            e.xy.emplace_back(s.elements, s.seconds);
            if (s.estimated) f.xy.emplace_back(s.frontLength, s.seconds);
        }
        e.markers = f.markers = false;
        byElements.series.push_back(e);
        if (r.method == "EST") byFront.series.push_back(f);
    }
    byFront.title = "EST: time per propagation step vs active front length";
    byElements.width = byFront.width = 800;
    byElements.height = byFront.height = 520;
    save("step_time_vs_elements.png", byElements);
    save("step_time_vs_front_length.png", byFront);
    // Peak memory against the largest BEM mesh of the run, per method family.
    PlotSpec memory;
    memory.title = "peak memory vs BEM elements";
    memory.x = {"surface + crack triangles at the end", true};
    memory.y = {"peak resident memory [MB]", true};
    std::map<std::string, PlotSeries> families;
    for (const auto& r : runs) {
        const std::string family = r.method.rfind("HYB", 0) == 0 ? "HYBRID" : r.method;
        PlotSeries& s = families[family];
        s.label = family;
        s.lines = false;
        s.xy.emplace_back(maxElements(r), r.peakMegabytes);
    }
    for (auto& [name, s] : families) memory.series.push_back(s);
    save("memory_vs_elements.png", memory);
    return written;
}

}  // namespace accuracy
