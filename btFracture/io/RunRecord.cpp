// SPDX-License-Identifier: Zlib
#include <btFracture/io/RunRecord.h>

#include <btFracture/io/AtomicFile.h>

#include <nlohmann/json.hpp>

#include <ctime>

namespace btfracture {

std::string utcTimestamp(std::chrono::system_clock::time_point time) {
    const std::time_t t = std::chrono::system_clock::to_time_t(time);
    std::tm utc{};
    gmtime_r(&t, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

void writeRunRecord(const std::string& path, const RunRecord& r) {
    nlohmann::ordered_json j;
    j["program"] = r.program;
    j["version"] = r.version;
    j["source_revision"] = r.sourceRevision;
    j["command_line"] = r.commandLine;
    j["working_directory"] = r.workingDirectory;
    j["scene"] = nlohmann::ordered_json::object();
    j["inputs"] = nlohmann::ordered_json::array();
    for (const RunInput& input : r.inputs) {
        nlohmann::ordered_json file = {{"role", input.role}, {"path", input.path}, {"sha256", input.sha256}};
        if (input.role == "scene" && j["scene"].empty())
            j["scene"] = {{"path", input.path}, {"sha256", input.sha256}};
        j["inputs"].push_back(file);
    }
    j["bullet_precision"] = r.bulletPrecision;
    j["seed"] = r.seed;
    j["threads"] = {{"requested", r.threadsRequested}, {"openmp", r.openmpThreads}, {"tbb", r.tbbThreads}};
    j["overrides"] = nlohmann::ordered_json::object();
    for (const auto& [option, value] : r.overrides) j["overrides"][option] = value;
    j["steps"] = {
        {"requested", r.stepsRequested}, {"taken", r.stepsTaken}, {"dt_s", r.dt}, {"substeps", r.substeps}};
    j["start_time"] = r.startTime;
    j["end_time"] = r.endTime;
    j["exit_status"] = r.exitStatus;
    if (!r.stopReason.empty()) j["stop_reason"] = r.stopReason;
    j["seconds"] = {{"setup", r.seconds.setup},
                    {"rigid_body", r.seconds.rigidBody},
                    {"fracture", r.seconds.fracture},
                    {"output", r.seconds.output},
                    {"total", r.seconds.total}};
    j["bodies"] = r.bodies;
    j["breakable_bodies"] = r.breakableBodies;
    j["fracture_events"] = r.fractureEvents;
    j["fragments"] = r.fragments;
    j["max_k_over_kc"] = r.maxLoadRatio;
    j["peak_memory_mb"] = r.peakMemoryMegabytes;
    j["outputs"] = r.outputs;

    writeFileAtomically(path, j.dump(2) + "\n");
}

}  // namespace btfracture
