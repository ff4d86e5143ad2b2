// SPDX-License-Identifier: Zlib
// Replays inputs through a fuzz target's LLVMFuzzerTestOneInput without libFuzzer, so that the
// seed corpus and every input that once crashed (fuzz/regressions/) run in the ordinary test
// suite with any compiler. Arguments: files, or folders whose files are replayed in name order.
// With --mutate N, also a short seeded fuzz run: N random mutations (byte flips, inserted or
// deleted runs, spliced pieces of other inputs) of the inputs, the same N inputs every run.
// A crash or an escaping exception fails the test.
#include "FuzzSupport.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

// One random edit of `bytes`; `other` is a second input to splice from.
std::string mutate(std::string bytes, const std::string& other, std::mt19937_64& rng) {
    auto pick = [&](std::size_t n) { return n == 0 ? std::size_t(0) : std::size_t(rng() % n); };
    switch (rng() % 5) {
        case 0:  // flip bits of a few bytes
            for (int k = 0; k < 1 + int(rng() % 4) && !bytes.empty(); ++k)
                bytes[pick(bytes.size())] ^= char(1 << (rng() % 8));
            break;
        case 1:  // overwrite a byte with an interesting one
            if (!bytes.empty()) bytes[pick(bytes.size())] = "\0\n-9e.,;{}[]\"\xff"[rng() % 15];
            break;
        case 2:  // delete a run
            if (!bytes.empty()) {
                const std::size_t at = pick(bytes.size());
                bytes.erase(at, 1 + pick(std::min<std::size_t>(64, bytes.size() - at)));
            }
            break;
        case 3:  // duplicate a run
            if (!bytes.empty()) {
                const std::size_t at = pick(bytes.size()),
                                  n = 1 + pick(std::min<std::size_t>(64, bytes.size() - at));
                bytes.insert(pick(bytes.size() + 1), bytes.substr(at, n));
            }
            break;
        default:  // splice a piece of another input
            if (!other.empty()) {
                const std::size_t at = pick(other.size()),
                                  n = 1 + pick(std::min<std::size_t>(256, other.size() - at));
                bytes.insert(pick(bytes.size() + 1), other.substr(at, n));
            }
    }
    return bytes;
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::vector<fs::path> inputs;
    long mutations = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--mutate" && i + 1 < argc) {
            mutations = std::stol(argv[++i]);
            continue;
        }
        const fs::path path(argv[i]);
        if (fs::is_directory(path)) {
            std::vector<fs::path> files;
            for (const auto& entry : fs::directory_iterator(path))
                if (entry.is_regular_file()) files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            inputs.insert(inputs.end(), files.begin(), files.end());
        } else if (fs::is_regular_file(path)) {
            inputs.push_back(path);
        } else {
            std::fprintf(stderr, "replay: no such file or folder: %s\n", argv[i]);
            return 2;
        }
    }
    std::vector<std::string> contents;
    for (const fs::path& path : inputs) {
        std::ifstream in(path, std::ios::binary);
        contents.emplace_back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(contents.back().data()),
                               contents.back().size());
    }
    std::printf("replayed %zu inputs\n", inputs.size());
    if (inputs.empty()) return 1;
    std::mt19937_64 rng(20261124);
    for (long k = 0; k < mutations; ++k) {
        std::string bytes = contents[k % contents.size()];
        for (int edits = 1 + int(rng() % 4); edits > 0; --edits)
            bytes = mutate(std::move(bytes), contents[rng() % contents.size()], rng);
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    if (mutations > 0) std::printf("ran %ld seeded mutations\n", mutations);
    return 0;
}
