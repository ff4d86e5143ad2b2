// SPDX-License-Identifier: Zlib
#include <btFracture/io/AtomicFile.h>

#include <btFracture/core/Error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace btfracture {

void writeFileAtomically(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out) throw Error("cannot write '" + temporary + "': " + std::strerror(errno));
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw Error("cannot rename '" + temporary + "' to '" + path + "': " + reason);
    }
}

}  // namespace btfracture
