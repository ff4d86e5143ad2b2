// SPDX-License-Identifier: Zlib
#pragma once
// One run of the accuracy study (one case, one method): what it cost and what it produced. Runs
// happen in a child process (IsolatedRun.h), so the result travels as text.
#include <btFracture/core/TriangleMesh.h>

#include <string>
#include <vector>

namespace accuracy {

// One propagation step of a solver-level run.
struct StepSample {
    int elements = 0;          // BEM elements before the step: surface + crack triangles
    double frontLength = 0.0;  // length of the front that can still move [m]
    int frontNodes = 0;        // front nodes the step evaluated
    double seconds = 0.0;      // SIFs + growth of the step [s]
    bool estimated = false;    // the step used EST
    double meanKI = 0.0,
           meanKeff = 0.0;  // over the whole front before the step [Pa m^(1/2)]; 0: not measured
};

struct RunResult {
    std::string caseName, method;     // method label: FULL, EST, HYB-25 ... (threshold in % of FULL's crack)
    int threshold = 0;                // HYBRID's element threshold (0: not HYBRID)
    int surfaceTriangles = 0;         // BEM surface mesh (scenes: the target)
    double bodySize = 0.0;            // bounding-box diagonal of the body [m]
    int crackTriangles = 0;           // at the end (scenes: of the first event)
    int steps = 0;                    // propagation steps (solver cases)
    int events = 0;                   // scenes: engine calls that broke the body or its kept piece
    double firstEventSeconds = 0.0;   // scenes: engine time of the first event alone [s]
    double bemSeconds = 0.0;          // BEM set-up (scenes: engine's BEM share) [s]
    double fractureSeconds = 0.0;     // SIFs, initiation, propagation [s]
    double geometrySeconds = 0.0;     // level-set cuts and fragments (scenes only) [s]
    double otherEngineSeconds = 0.0;  // scenes: engine calls that broke nothing (no split reported) [s]
    double rigidSeconds = 0.0;        // Bullet stepping, swap and replay (scenes only) [s]
    double peakMegabytes = 0.0;       // peak resident memory of the run's process [MB]
    double sifError = -1.0;           // relative SIF error against the case's reference (-1: none)
    int fragments = -1;               // scenes only
    double mottKs = -1.0;             // Kolmogorov-Smirnov distance to Mott's distribution (-1: none)
    std::vector<StepSample> stepSamples;
    std::vector<double> fragmentVolumes;  // relative to the original body
    btfracture::TriangleMesh surface;     // the fracture surface (crack sheets or fragment faces) [m]
    // Filled by the driver after all runs of the case: distance of `surface` to the reference
    // run's, relative to the body size (-1: none).
    double surfaceHausdorff = -1.0, surfaceMean = -1.0;
    std::string note;  // "run failed (<why>)" when the run gave no result (failed())

    bool failed() const { return note.rfind("run failed", 0) == 0; }

    // Everything the fracture engine spent (BEM, cracks, geometry): the paper's t_f [s].
    double engineSeconds() const {
        return bemSeconds + fractureSeconds + geometrySeconds + otherEngineSeconds;
    }
};

std::string serialize(const RunResult& result);
RunResult deserialize(const std::string& text);  // throws btfracture::Error on malformed text

}  // namespace accuracy
