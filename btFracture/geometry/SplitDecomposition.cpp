// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/SplitDecomposition.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Intersection.h>
#include <btFracture/core/MassProperties.h>
#include <btFracture/geometry/ConvexHull.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace btfracture {

namespace {

// Planar polygons stored back to back: polygon i is points[start[i]] .. points[start[i + 1] - 1].
struct Polygons {
    std::vector<Eigen::Vector3d> points;
    std::vector<int> start{0};
    int size() const { return static_cast<int>(start.size()) - 1; }
    void close(std::size_t first) {
        if (points.size() - first < 3)
            points.resize(first);  // a sliver of the plane: no area
        else
            start.push_back(static_cast<int>(points.size()));
    }
};

struct Part {
    Polygons surface;                      // the mesh's triangles clipped to the part's box
    std::vector<Eigen::Vector3d> corners;  // candidates for its hull's corners
    std::vector<int> samples;              // inside sample points that lie in the part
    Eigen::Vector3d boxLo, boxHi;          // the cut planes around it (the mesh's box where uncut)
    Eigen::Vector3d lo, hi;                // bounding box of the corners
    double hullVolume = 0.0;
    double excess = 0.0;  // hull volume beyond the part's volume [m^3]
    bool splittable = true;
};

// Grid points inside the closed mesh: per column along z, the mesh's crossings sorted, inside
// between alternate pairs. Columns with an odd crossing count (a grazed edge) are left out.
std::vector<Eigen::Vector3d> insideSamples(const TriangleMesh& mesh, const Eigen::AlignedBox3d& box,
                                           int target) {
    const Eigen::Vector3d& lo = box.min();
    const Eigen::Vector3d extent = box.sizes();
    const double cell = std::max(std::cbrt(extent.prod() / target), extent.maxCoeff() / 256.0);
    if (!(cell > 0.0)) return {};
    Eigen::Vector3i n;
    for (int a = 0; a < 3; ++a) n[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cell)));
    const Eigen::Vector3d h = extent.cwiseQuotient(n.cast<double>());
    // Column offsets away from the cell centres: grid-aligned meshes (boxes) then put no edge
    // through a column.
    const auto coordinate = [&](int a, int i, double offset) { return lo[a] + (i + 0.5 + offset) * h[a]; };
    std::vector<std::vector<double>> crossings(static_cast<std::size_t>(n.x()) * n.y());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d& a = mesh.vertices[t[0]];
        const Eigen::Vector3d& b = mesh.vertices[t[1]];
        const Eigen::Vector3d& c = mesh.vertices[t[2]];
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
        if (area == 0.0) continue;  // vertical: no column crosses it
        const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
        const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
        const int i0 = std::max(0, static_cast<int>(std::floor((x0 - lo.x()) / h.x() - 0.6)));
        const int i1 = std::min(n.x() - 1, static_cast<int>(std::ceil((x1 - lo.x()) / h.x())));
        const int j0 = std::max(0, static_cast<int>(std::floor((y0 - lo.y()) / h.y() - 0.6)));
        const int j1 = std::min(n.y() - 1, static_cast<int>(std::ceil((y1 - lo.y()) / h.y())));
        for (int i = i0; i <= i1; ++i) {
            const double x = coordinate(0, i, 0.0123);
            if (x < x0 || x > x1) continue;
            for (int j = j0; j <= j1; ++j) {
                const double y = coordinate(1, j, 0.0371);
                if (y < y0 || y > y1) continue;
                const double wa = ((b.x() - x) * (c.y() - y) - (b.y() - y) * (c.x() - x)) / area;
                const double wb = ((c.x() - x) * (a.y() - y) - (c.y() - y) * (a.x() - x)) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                crossings[static_cast<std::size_t>(i) * n.y() + j].push_back(wa * a.z() + wb * b.z() +
                                                                             wc * c.z());
            }
        }
    }
    std::vector<Eigen::Vector3d> samples;
    for (int i = 0; i < n.x(); ++i)
        for (int j = 0; j < n.y(); ++j) {
            std::vector<double>& z = crossings[static_cast<std::size_t>(i) * n.y() + j];
            if (z.empty() || z.size() % 2 != 0) continue;
            std::sort(z.begin(), z.end());
            for (std::size_t k = 0; k + 1 < z.size(); k += 2) {
                const int first = std::max(0, static_cast<int>(std::ceil((z[k] - lo.z()) / h.z() - 0.5)));
                for (int m = first; m < n.z(); ++m) {
                    const double zm = coordinate(2, m, 0.0);
                    if (zm > z[k + 1]) break;
                    if (zm >= z[k])
                        samples.emplace_back(coordinate(0, i, 0.0123), coordinate(1, j, 0.0371), zm);
                }
            }
        }
    return samples;
}

void evaluate(Part& part, double meshVolume, std::size_t totalSamples) {
    part.lo = part.hi = part.corners.front();
    for (const auto& p : part.corners) {
        part.lo = part.lo.cwiseMin(p);
        part.hi = part.hi.cwiseMax(p);
    }
    part.hullVolume = convexHullVolume(part.corners, "split part");
    const double volume = meshVolume * double(part.samples.size()) / double(totalSamples);
    part.excess = part.hullVolume - volume;
}

// Cuts parts of one mesh's solid. A part's corners are the corners of its surface polygons (the
// clipped triangles, whose edges on the cut planes bound its caps) and the corners of its box of
// cut planes that lie inside the solid: together the corners of the part, so their hull holds it.
class Splitter {
public:
    Splitter(const TriangleMesh& mesh, const Eigen::AlignedBox3d& box,
             const std::vector<Eigen::Vector3d>& samples)
        : mesh_(mesh), samples_(samples), lo_(box.min()), hi_(box.max()) {}

    // The part cut by the plane x[axis] = value into its sides x[axis] <= value and >= value.
    std::pair<Part, Part> split(const Part& part, int axis, double value) const {
        std::pair<Part, Part> sides;
        Part& below = sides.first;
        Part& above = sides.second;
        below.boxLo = above.boxLo = part.boxLo;
        below.boxHi = above.boxHi = part.boxHi;
        below.boxHi[axis] = above.boxLo[axis] = value;
        for (const auto& p : part.corners) {
            if (p[axis] <= value) below.corners.push_back(p);
            if (p[axis] >= value) above.corners.push_back(p);
        }
        for (int s = 0; s < part.surface.size(); ++s) {
            const Eigen::Vector3d* polygon = part.surface.points.data() + part.surface.start[s];
            const int count = part.surface.start[s + 1] - part.surface.start[s];
            const std::size_t belowFirst = below.surface.points.size(),
                              aboveFirst = above.surface.points.size();
            for (int k = 0; k < count; ++k) {
                const Eigen::Vector3d& p = polygon[k];
                const Eigen::Vector3d& q = polygon[(k + 1) % count];
                const double dp = p[axis] - value, dq = q[axis] - value;
                if (dp <= 0.0) below.surface.points.push_back(p);
                if (dp >= 0.0) above.surface.points.push_back(p);
                if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
                    Eigen::Vector3d x = p + (dp / (dp - dq)) * (q - p);
                    x[axis] = value;
                    below.surface.points.push_back(x);
                    above.surface.points.push_back(x);
                    below.corners.push_back(x);
                    above.corners.push_back(x);
                }
            }
            below.surface.close(belowFirst);
            above.surface.close(aboveFirst);
        }
        for (Part* side : {&below, &above}) addInsideBoxCorners(*side, axis, value);
        for (int i : part.samples) (samples_[i][axis] <= value ? below : above).samples.push_back(i);
        return sides;
    }

private:
    // The corners of the part's box on its new plane x[axis] = value that lie inside the solid.
    // Corners on the mesh's bounding box are left out: they are on the surface at most, where
    // the surface polygons already reach.
    void addInsideBoxCorners(Part& part, int axis, double value) const {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (const double u : {part.boxLo[a1], part.boxHi[a1]})
            for (const double v : {part.boxLo[a2], part.boxHi[a2]}) {
                if (u == lo_[a1] || u == hi_[a1] || v == lo_[a2] || v == hi_[a2]) continue;
                Eigen::Vector3d corner;
                corner[a1] = u;
                corner[a2] = v;
                corner[axis] = value;
                if (isInside(corner)) part.corners.push_back(corner);
            }
    }

    bool isInside(const Eigen::Vector3d& p) const {
        return std::abs(windingNumber(mesh_.vertices, mesh_.triangles, p)) > 0.5;
    }

    const TriangleMesh& mesh_;
    const std::vector<Eigen::Vector3d>& samples_;
    const Eigen::Vector3d lo_, hi_;  // the mesh's bounding box
};

}  // namespace

SplitDecomposition splitDecomposition(const TriangleMesh& mesh, const SplitDecompositionOptions& options) {
    const std::string name = mesh.name.empty() ? std::string("<unnamed mesh>") : mesh.name;
    if (options.maxPieces < 1 || !(options.concavity >= 0.0) || options.volumeSamples < 1) {
        std::ostringstream out;
        out << name << ": split decomposition options out of range (max pieces " << options.maxPieces
            << ", need >= 1; concavity " << options.concavity << ", need >= 0; volume samples "
            << options.volumeSamples << ", need >= 1)";
        throw Error(out.str());
    }
    SplitDecomposition result;
    result.meshVolume = mesh.triangles.empty() ? 0.0 : computeMassProperties(mesh).volume;
    if (!(result.meshVolume > 0.0))
        throw Error(name + ": split decomposition needs a closed mesh with volume");

    Eigen::AlignedBox3d box;
    for (const auto& v : mesh.vertices) box.extend(v);
    const std::vector<Eigen::Vector3d> samples = insideSamples(mesh, box, options.volumeSamples);
    const Splitter splitter(mesh, box, samples);
    std::vector<Part> parts(1);
    Part& root = parts.front();
    root.corners = mesh.vertices;
    root.boxLo = box.min();
    root.boxHi = box.max();
    for (const auto& t : mesh.triangles) {
        const std::size_t first = root.surface.points.size();
        for (int v : t) root.surface.points.push_back(mesh.vertices[v]);
        root.surface.close(first);
    }
    root.samples.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) root.samples[i] = static_cast<int>(i);
    evaluate(root, result.meshVolume, std::max<std::size_t>(1, samples.size()));
    // Without samples (a mesh thinner than the grid) no part volume is known: one piece.
    if (samples.empty()) root.splittable = false;

    const double tolerance = options.concavity * result.meshVolume;
    // Volumes within `tie` of each other are equal: the first in order wins, so that the last
    // bits of a hull volume (summation order, fused multiply-add) never choose the cut.
    const double tie = 1e-9 * result.meshVolume;
    while (static_cast<int>(parts.size()) < options.maxPieces) {
        const auto cuttable = [&](const Part& p) { return p.splittable && p.excess > tolerance; };
        double largestExcess = -std::numeric_limits<double>::infinity();
        for (const Part& p : parts)
            if (cuttable(p)) largestExcess = std::max(largestExcess, p.excess);
        const auto worstPart = std::find_if(parts.begin(), parts.end(), [&](const Part& p) {
            return cuttable(p) && p.excess >= largestExcess - tie;
        });
        if (worstPart == parts.end()) break;
        Part& part = *worstPart;
        // Nine candidate planes, cut in parallel; the first with the smallest summed hull volume
        // wins (the same on any thread count).
        std::vector<std::pair<int, double>> planes;
        for (int axis = 0; axis < 3; ++axis) {
            const double width = part.hi[axis] - part.lo[axis];
            if (!(width > 1e-9 * (part.hi - part.lo).norm())) continue;
            for (const double fraction : {0.25, 0.5, 0.75})
                planes.emplace_back(axis, part.lo[axis] + fraction * width);
        }
        std::vector<std::pair<Part, Part>> cuts(planes.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int c = 0; c < static_cast<int>(planes.size()); ++c) {
            cuts[c] = splitter.split(part, planes[c].first, planes[c].second);
            if (cuts[c].first.surface.size() == 0 || cuts[c].second.surface.size() == 0) continue;
            evaluate(cuts[c].first, result.meshVolume, samples.size());
            evaluate(cuts[c].second, result.meshVolume, samples.size());
        }
        const auto valid = [](const std::pair<Part, Part>& cut) {
            return cut.first.surface.size() != 0 && cut.second.surface.size() != 0;
        };
        const auto summed = [](const std::pair<Part, Part>& cut) {
            return cut.first.hullVolume + cut.second.hullVolume;
        };
        double smallest = std::numeric_limits<double>::infinity();
        for (const auto& cut : cuts)
            if (valid(cut)) smallest = std::min(smallest, summed(cut));
        const auto chosen = std::find_if(cuts.begin(), cuts.end(), [&](const std::pair<Part, Part>& cut) {
            return valid(cut) && summed(cut) <= smallest + tie;
        });
        if (chosen == cuts.end()) {  // no plane leaves surface on both sides
            part.splittable = false;
            continue;
        }
        std::pair<Part, Part> best = std::move(*chosen);
        part = std::move(best.first);
        parts.push_back(std::move(best.second));
    }
    for (Part& part : parts) {
        if (!(part.hullVolume > 0.0)) continue;  // flat: holds no volume
        result.hullVolume += part.hullVolume;
        result.pieces.push_back(std::move(part.corners));
    }
    return result;
}

}  // namespace btfracture
