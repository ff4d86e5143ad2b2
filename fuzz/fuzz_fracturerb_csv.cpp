// SPDX-License-Identifier: Zlib
// libFuzzer target: the FractureRB parameter CSV reader (io/FractureRbScene.h). btfracture::Error
// is the only accepted failure.
#include "FuzzSupport.h"

#include <btFracture/core/Error.h>
#include <btFracture/io/FractureRbScene.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    btfracture::fuzz::silenceLog();
    try {
        btfracture::parseFractureRbCsv(btfracture::fuzz::text(data, size), "fuzz.csv");
    } catch (const btfracture::Error&) {
    }
    return 0;
}
