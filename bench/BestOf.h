// SPDX-License-Identifier: Zlib
#pragma once
// Shortest wall time [s] of `runs` calls of `work`: the benchmarks' noise filter on a shared machine.
#include <btFracture/core/Timer.h>

#include <algorithm>
#include <functional>

namespace btfracture {

inline double bestOf(int runs, const std::function<void()>& work) {
    double best = 1e30;
    for (int i = 0; i < runs; ++i) {
        Timer timer;
        work();
        best = std::min(best, timer.seconds());
    }
    return best;
}

}  // namespace btfracture
