// SPDX-License-Identifier: Zlib
#pragma once
// Runs one benchmark run in a forked child process, so that each run's peak resident memory is
// measured on its own (getrusage of the child: ru_maxrss), a crash or an allocation failure
// loses only that run, and an optional address-space limit keeps a run that grows too large from
// exhausting the machine. The child's result comes back as text through a pipe.
#include <functional>
#include <string>

namespace btfracture {

struct IsolatedRun {
    bool ok = false;             // the child returned normally and its text arrived
    std::string text;            // what `run` returned (empty unless ok)
    std::string failure;         // otherwise why: the exception's message, the signal or exit status
    double peakMegabytes = 0.0;  // peak resident memory of the child [MB]
    double cpuSeconds = 0.0;     // user + system CPU time of the child, all its threads [s]
};

// Calls `run` in a child. `memoryLimitMegabytes` > 0 caps the child's address space
// (RLIMIT_AS): allocations beyond it throw std::bad_alloc, which fails the run instead of the
// machine. `cpuLimitSeconds` > 0 caps its CPU time, all threads (RLIMIT_CPU): the kernel ends a
// longer run (SIGXCPU) and the failure names the limit. The parent must not have started worker
// threads (OpenMP, TBB) before: fork copies only the calling thread.
IsolatedRun runIsolated(const std::function<std::string()>& run, double memoryLimitMegabytes = 0.0,
                        double cpuLimitSeconds = 0.0);

}  // namespace btfracture
