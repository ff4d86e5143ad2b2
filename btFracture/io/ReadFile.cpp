// SPDX-License-Identifier: Zlib
#include <btFracture/io/ReadFile.h>

#include <btFracture/core/Error.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace btfracture {

std::string readWholeFile(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + what + " '" + path + "': " + std::strerror(errno));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw Error("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    return bytes.str();
}

}  // namespace btfracture
