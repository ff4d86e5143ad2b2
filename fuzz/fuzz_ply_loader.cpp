// SPDX-License-Identifier: Zlib
// libFuzzer target: the PLY loader (io/PlyReader.h: ascii and both binary byte orders) followed
// by the closed-solid check that readMesh applies. btfracture::Error is the only accepted failure.
#include "FuzzSupport.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/io/PlyReader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    btfracture::fuzz::silenceLog();
    try {
        btfracture::TriangleMesh mesh = btfracture::parsePly(btfracture::fuzz::text(data, size), "fuzz.ply");
        btfracture::requireClosedSolid(mesh);
    } catch (const btfracture::Error&) {
    }
    return 0;
}
