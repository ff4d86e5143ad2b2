// SPDX-License-Identifier: Zlib
#include <btFracture/io/PolygonFan.h>

#include <btFracture/core/Log.h>

#include <algorithm>

namespace btfracture {

void PolygonFan::add(const std::vector<int>& corners) {
    for (size_t k = 1; k + 1 < corners.size(); ++k)
        mesh_.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    if (corners.size() > 3) {
        ++polygons_;
        maxCorners_ = std::max(maxCorners_, static_cast<int>(corners.size()));
    }
}

void PolygonFan::report(const std::string& file) const {
    if (polygons_ > 0)
        logf(LogLevel::Info, file, ": split ", polygons_, " polygon faces (up to ", maxCorners_,
             " corners) into triangle fans");
}

}  // namespace btfracture
