// SPDX-License-Identifier: Zlib
#pragma once
// The study's outputs from the collected runs: runs.csv (one row per run), steps.csv (one row per
// propagation step of the solver-level runs), table.md (the README table) and the PNG charts:
// error against fracture time per case (Pareto), step time against BEM elements and against
// active front length (§4.4), peak memory against elements.
#include "RunResult.h"

#include <string>
#include <vector>

namespace accuracy {

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs);
void writeStepsCsv(const std::string& path, const std::vector<RunResult>& runs);
void writeMarkdownTable(const std::string& path, const std::vector<RunResult>& runs);
// Writes the charts into `directory`; returns the file names written.
std::vector<std::string> writeCharts(const std::string& directory, const std::vector<RunResult>& runs);

}  // namespace accuracy
