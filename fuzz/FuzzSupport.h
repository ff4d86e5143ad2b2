// SPDX-License-Identifier: Zlib
#pragma once
// Shared by the libFuzzer targets: the entry point libFuzzer calls, and silence for btFracture's
// log (the fuzzers feed millions of malformed inputs; a line each would drown the output).
#include <btFracture/core/Log.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace btfracture::fuzz {

inline void silenceLog() {
    static const bool once = [] {
        setLogSink([](LogLevel, const std::string&) {});
        return true;
    }();
    (void)once;
}

inline std::string text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace btfracture::fuzz
