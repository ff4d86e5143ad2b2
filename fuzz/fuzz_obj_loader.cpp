// SPDX-License-Identifier: Zlib
// libFuzzer target: the OBJ loader (io/ObjReader.h) followed by the closed-solid check that
// readMesh applies (core/MeshCheck.h). A btfracture::Error is the expected answer to bad input;
// anything else (another exception, a crash, a sanitizer report, a hang) is a bug.
#include "FuzzSupport.h"

#include <btFracture/core/Error.h>
#include <btFracture/core/MeshCheck.h>
#include <btFracture/io/ObjReader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    btfracture::fuzz::silenceLog();
    try {
        btfracture::TriangleMesh mesh = btfracture::parseObj(btfracture::fuzz::text(data, size), "fuzz.obj");
        btfracture::requireClosedSolid(mesh);
    } catch (const btfracture::Error&) {
    }
    return 0;
}
