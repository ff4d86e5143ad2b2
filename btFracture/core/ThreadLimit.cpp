// SPDX-License-Identifier: Zlib
#include <btFracture/core/ThreadLimit.h>

#include <btFracture/core/Error.h>

#include <omp.h>
#include <tbb/global_control.h>

#include <string>

namespace btfracture {

struct ThreadLimit::Impl {
    int previousOpenmp = 0;
    std::unique_ptr<tbb::global_control> tbbLimit;
};

ThreadLimit::ThreadLimit(int threads) : impl_(std::make_unique<Impl>()) {
    if (threads < 0) throw Error("thread count must be >= 0 (0 = all cores), got " + std::to_string(threads));
    impl_->previousOpenmp = omp_get_max_threads();
    if (threads == 0) return;
    omp_set_num_threads(threads);
    impl_->tbbLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                            static_cast<size_t>(threads));
}

ThreadLimit::~ThreadLimit() {
    omp_set_num_threads(impl_->previousOpenmp);
}

int ThreadLimit::openmpThreads() {
    return omp_get_max_threads();
}

int ThreadLimit::tbbThreads() {
    return static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

}  // namespace btfracture
