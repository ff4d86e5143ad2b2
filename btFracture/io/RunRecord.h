// SPDX-License-Identifier: Zlib
#pragma once
// run.json: what made an output folder - program and version, source revision, command line,
// the input files with their SHA-256, seed, threads, the options that overrode the scene, start
// and end time, exit status, time per phase, event and fragment counts, the largest K/K_c, peak
// memory. Written last and atomically (a temporary file in the same folder, then a rename), so a
// folder's run.json always describes a finished run whole.
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace btfracture {

struct RunInput {
    std::string role;  // "scene", "fracturerb_csv", "mesh"
    std::string path;
    std::string sha256;
};

struct RunRecord {
    std::string program;
    std::string version;
    std::string sourceRevision;  // `git describe --always --dirty` of the build, or "unknown"
    std::vector<std::string> commandLine;
    std::string workingDirectory;
    std::vector<RunInput> inputs;  // the scene first
    std::string bulletPrecision;   // "float" or "double"
    std::uint64_t seed = 0;
    int threadsRequested = 0;  // 0: all cores
    int openmpThreads = 0, tbbThreads = 0;
    std::vector<std::pair<std::string, std::string>> overrides;  // option -> its value as given
    int stepsRequested = 0, stepsTaken = 0, substeps = 1;
    double dt = 0.0;                 // [s]
    std::string startTime, endTime;  // ISO 8601, UTC
    int exitStatus = 0;
    std::string stopReason;  // why a run ended early (exit status 1 or 3); empty otherwise
    struct Seconds {
        double setup = 0.0, rigidBody = 0.0, fracture = 0.0, output = 0.0, total = 0.0;
    } seconds;
    int bodies = 0, breakableBodies = 0, fractureEvents = 0, fragments = 0;
    double maxLoadRatio = 0.0;         // largest K_eff / K_c of any crack front (FractureStatistics)
    double peakMemoryMegabytes = 0.0;  // maximum resident set size
    std::vector<std::string> outputs;  // files written, by name or pattern
};

// "2026-11-27T01:02:03Z"
std::string utcTimestamp(std::chrono::system_clock::time_point time);

// Writes `record` as JSON to `path` through `path`.tmp and a rename. Throws btfracture::Error
// naming the file when it cannot be written.
void writeRunRecord(const std::string& path, const RunRecord& record);

}  // namespace btfracture
