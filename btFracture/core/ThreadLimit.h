// SPDX-License-Identifier: Zlib
#pragma once
// Caps the worker threads of OpenMP and TBB (the libraries btFracture parallelises with) while
// the object lives. Results never depend on the thread count; only the speed does.
#include <memory>

namespace btfracture {

class ThreadLimit {
public:
    // `threads` >= 1 caps both libraries at that many threads; 0 keeps their defaults (all
    // cores). Throws btfracture::Error for negative values.
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

    // Threads OpenMP and TBB may use now.
    static int openmpThreads();
    static int tbbThreads();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace btfracture
