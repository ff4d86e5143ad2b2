// SPDX-License-Identifier: Zlib
#pragma once
// Runs one study run in a forked child process, so that each run's peak resident memory can be
// measured on its own (getrusage of the child: ru_maxrss) and a crash loses only that run.
#include "RunResult.h"

#include <functional>

namespace accuracy {

// Calls `run` in a child; returns its result with peakMegabytes set to the child's peak RSS.
// The parent must not have started worker threads (OpenMP, TBB) before: fork copies only the
// calling thread. A child that dies or writes nothing gives a result with `note` saying so.
RunResult runIsolated(const std::function<RunResult()>& run, const std::string& caseName,
                      const std::string& method);

}  // namespace accuracy
