// SPDX-License-Identifier: Zlib
// libFuzzer target: the JSON scene parser (io/SceneFile.h). Mesh paths are resolved against a
// folder that does not exist, so no input reaches the file system beyond an existence check.
// btfracture::Error is the only accepted failure.
#include "FuzzSupport.h"

#include <btFracture/core/Error.h>
#include <btFracture/io/SceneFile.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    btfracture::fuzz::silenceLog();
    try {
        btfracture::parseScene(btfracture::fuzz::text(data, size), "fuzz.json", "/nonexistent-fuzz-dir");
    } catch (const btfracture::Error&) {
    }
    return 0;
}
