// SPDX-License-Identifier: Zlib
#pragma once
// Polygon faces of OBJ and PLY files become triangle fans from their first corner; the readers
// count the split polygons and say so once per file.
#include <btFracture/core/TriangleMesh.h>

#include <string>
#include <vector>

namespace btfracture {

class PolygonFan {
public:
    explicit PolygonFan(TriangleMesh& mesh) : mesh_(mesh) {}
    // Appends the polygon (at least 3 corners, indices already checked) as triangles.
    void add(const std::vector<int>& corners);
    // Logs "<file>: split N polygons ... into triangles" when any face had more than 3 corners.
    void report(const std::string& file) const;

private:
    TriangleMesh& mesh_;
    int polygons_ = 0;
    int maxCorners_ = 3;
};

}  // namespace btfracture
