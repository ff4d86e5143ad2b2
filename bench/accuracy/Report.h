// SPDX-License-Identifier: Zlib
#pragma once
// The study's outputs from the collected runs: runs.csv (one row per run), steps.csv (one row per
// propagation step of the solver-level runs) and table.md (the README table). The charts are
// scripts/charts/accuracy_charts.py's, from runs.csv and steps.csv.
#include "RunResult.h"

#include <string>
#include <vector>

namespace accuracy {

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs);
void writeStepsCsv(const std::string& path, const std::vector<RunResult>& runs);
void writeMarkdownTable(const std::string& path, const std::vector<RunResult>& runs);

}  // namespace accuracy
