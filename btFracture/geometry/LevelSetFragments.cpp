// SPDX-License-Identifier: Zlib
// LevelSetBody::fragments(): segmentation of the cut object into connected components and the
// level set, mass, meshes and hull of each (paper §5.2, §5.3). The second of the two
// translation units that include OpenVDB.
//
// Each crack slab is a numerical gap 1.7 voxels thick. A fragment's own level set puts its
// surface back on the crack sheet itself: near a crack (within the narrow band), with s the
// signed distance to the nearest sheet triangle along its normal n, and L+ / L- the fragments
// found 2-5 voxels along +n / -n,
//   - L+ != L- (the crack separates here): phi_F = max(phi_solid, -s) for F = L+ and
//     max(phi_solid, +s) for F = L-, so the slab's material is split between the two sides;
//   - L+ == L- == F (the crack ends inside F, "incomplete"): phi_F = phi_solid, the slab is
//     filled for mass, collision and BEM surface, and the crack is carried into F's own body;
//   - only one of them found (the sheet meets the surface or another slab there): that fragment
//     takes the whole voxel, phi_F = phi_solid.
// Elsewhere phi_F is the object's distance inside F and positive outside; slab voxels that no
// crack voxel gives to F are outside F (each voxel's material counts for one fragment only).
#include <btFracture/geometry/LevelSetBody.h>

#include <btFracture/core/ClosestPoint.h>
#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>
#include <btFracture/geometry/ConvexHull.h>
#include <btFracture/geometry/MeshDecimation.h>
#include <btFracture/geometry/internal/LevelSetGrids.h>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace btfracture {
namespace {

using namespace levelset;
using openvdb::BoolGrid;

// Largest fragment volume over its parent's before a cut counts as degenerate.
constexpr double kMaxFragmentToParentVolume = 2.0;

// Where a crack voxel looks for the fragment on either side of its sheet [voxels from the sheet]:
// just past the slab's half-width (0.85 voxel: a chip one voxel thick between two slabs is found
// there), beyond the slab, and where sheets cross or run close, beyond the neighbour's slab.
constexpr double kSideProbes[] = {1.0, 2.0, 3.0, 4.0, 5.0};

// A voxel within the narrow band of a crack sheet, with the fragments on either side.
struct CrackVoxel {
    Coord ijk;
    double signedDistance;  // to the nearest sheet triangle, along its normal [m]
    int triangle;           // index into the body's crack triangles
    int plus, minus;        // fragment labels kSideProbes along +n / -n, -1 if none
};

// Convex hull of every voxel that integrateMass counts for phi (phi below half a voxel
// diagonal; interior tiles as boxes), each as its corners: the shape of a piece whose zero
// isosurface does not hold the volume the level set measures (a flake about a voxel thick meshes
// to next to nothing). Mass and inertia still come from the level set; its centre of mass, a
// weighted mean of points in these voxels, lies inside this hull.
TriangleMesh voxelHull(const FloatGrid& phi, const std::string& name) {
    std::vector<Eigen::Vector3d> corners;
    const float counted = static_cast<float>(kVoxelHalfDiagonal * phi.voxelSize()[0]);
    for (auto it = phi.tree().cbeginValueAll(); it; ++it) {
        if (!(*it < counted)) continue;
        const openvdb::CoordBBox box = it.getBoundingBox();  // one voxel, or a tile
        const openvdb::Vec3d lo = phi.indexToWorld(box.min().asVec3d() - openvdb::Vec3d(0.5)),
                             hi = phi.indexToWorld(box.max().asVec3d() + openvdb::Vec3d(0.5));
        for (int k = 0; k < 8; ++k)
            corners.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    }
    if (corners.empty()) throw Error(name + ": no voxel of the fragment is inside its level set");
    return convexHullMesh(corners, name);
}

struct Component {
    BoolGrid::Ptr mask;
    openvdb::Index64 voxels = 0;
    Coord firstVoxel;  // first active voxel in tree order (deterministic tie-break)
};

// Extends the fragment labels two voxels outward through the voxels just outside the surface
// (never into a crack slab), so that each partially filled surface voxel belongs to exactly one
// fragment and probes that land beside the surface find their side. Each ring reads the previous
// one; a voxel touching several fragments takes the lowest label (deterministic).
void labelSurfaceShell(Int32Grid& labels, const LevelSetBody::Impl& body) {
    const float shell = 2.0f * static_cast<float>(body.voxelSize);
    auto objectAcc = body.object->getConstAccessor();
    auto crackAcc = body.crack->getConstAccessor();
    std::vector<Coord> candidates;
    for (auto it = body.object->cbeginValueOn(); it; ++it)
        if (*it >= 0.0f && *it < shell && !(crackAcc.getValue(it.getCoord()) < 0.0f))
            candidates.push_back(it.getCoord());
    auto labelAcc = labels.getAccessor();
    std::vector<std::pair<Coord, int>> found;
    for (int ring = 0; ring < 2; ++ring) {
        found.clear();
        for (const Coord& ijk : candidates) {
            if (labelAcc.getValue(ijk) >= 0) continue;
            int label = -1;
            for (const Coord& d : {Coord(1, 0, 0), Coord(-1, 0, 0), Coord(0, 1, 0), Coord(0, -1, 0),
                                   Coord(0, 0, 1), Coord(0, 0, -1)}) {
                const int l = labelAcc.getValue(ijk + d);
                if (l >= 0 && (label < 0 || l < label)) label = l;
            }
            if (label >= 0) found.emplace_back(ijk, label);
        }
        for (const auto& [ijk, label] : found) labelAcc.setValueOn(ijk, label);
    }
}

// The connected pieces of phi's interior (6-connected voxels with phi < 0), one mask each.
std::vector<BoolGrid::Ptr> interiorPieces(const FloatGrid& phi) {
    std::vector<BoolGrid::Ptr> pieces;
    serially([&] {
        BoolGrid::Ptr interior = openvdb::tools::sdfInteriorMask(phi);
        openvdb::tools::extractActiveVoxelSegmentMasks(*interior, pieces);
    });
    return pieces;
}

// Keeps, of phi's interior, only the piece that holds `component`: crack voxels whose side probes
// reach past another slab can hand phi voxels that do not touch it (islands a voxel or two
// across, which the fragment's own body, §5.3, would split off as pieces at its next event).
void dropIslands(FloatGrid& phi, const BoolGrid& component, float background) {
    const std::vector<BoolGrid::Ptr> pieces = interiorPieces(phi);
    if (pieces.size() < 2) return;
    auto componentAcc = component.getConstAccessor();
    auto phiAcc = phi.getAccessor();
    for (const BoolGrid::Ptr& piece : pieces) {
        bool holdsComponent = false;
        for (auto it = piece->cbeginValueOn(); it && !holdsComponent; ++it)
            holdsComponent = componentAcc.isValueOn(it.getCoord());
        if (holdsComponent) continue;
        for (auto it = piece->cbeginValueOn(); it; ++it) phiAcc.setValueOff(it.getCoord(), background);
    }
}

// Puts a surface between every two face-neighbour voxels of the band that are both off (+-background)
// with opposite signs: a filled crack voxel beside a slab voxel left outside is such a pair, and
// OpenVDB meshes only where a voxel is on, so the fragment's surface would have a hole there. Both
// turn on at +-half a voxel (the surface on their shared face); voxels at half a voxel or more
// count as wholly inside or outside in the mass, so the volume does not change. Returns the pairs.
int closeSignJumps(FloatGrid& phi, const openvdb::BoolTree& band) {
    const float half = static_cast<float>(0.5 * phi.voxelSize()[0]);
    std::vector<std::pair<Coord, float>> turnOn;
    int pairs = 0;
    {
        auto acc = phi.getConstAccessor();
        for (auto it = band.cbeginValueOn(); it; ++it) {
            const Coord c = it.getCoord();
            if (acc.isValueOn(c)) continue;
            const bool inside = acc.getValue(c) < 0.0f;
            for (int axis = 0; axis < 3; ++axis) {
                Coord n = c;
                n[axis] += 1;
                if (acc.isValueOn(n) || (acc.getValue(n) < 0.0f) == inside) continue;
                ++pairs;
                turnOn.emplace_back(c, inside ? -half : half);
                turnOn.emplace_back(n, inside ? half : -half);
            }
        }
    }
    auto acc = phi.getAccessor();
    for (const auto& [ijk, value] : turnOn) acc.setValueOn(ijk, value);
    return pairs;
}

// Connected components of the object's interior (6-connected voxels), in a deterministic order
// (most voxels first, then lowest first voxel), without dust: components of too few voxels to
// matter (their volume and count are added to dustVolume and dustCount).
std::vector<Component> componentsAboveDust(const LevelSetBody::Impl& body, const FragmentSettings& settings,
                                           double& dustVolume, int& dustCount) {
    std::vector<BoolGrid::Ptr> masks = interiorPieces(*body.object);
    std::vector<Component> components;
    for (auto& mask : masks) {
        Component c;
        c.voxels = mask->activeVoxelCount();
        if (c.voxels == 0) continue;
        c.firstVoxel = mask->cbeginValueOn().getCoord();  // first in tree order
        c.mask = mask;
        components.push_back(std::move(c));
    }
    std::sort(components.begin(), components.end(), [](const Component& x, const Component& y) {
        return std::tie(y.voxels, x.firstVoxel) < std::tie(x.voxels, y.firstVoxel);
    });
    const double voxelVolume = body.voxelSize * body.voxelSize * body.voxelSize;
    while (!components.empty() && static_cast<double>(components.back().voxels) * voxelVolume <=
                                      settings.dustMaxFraction * body.originalVolume) {
        dustVolume += static_cast<double>(components.back().voxels) * voxelVolume;
        ++dustCount;
        components.pop_back();
    }
    return components;
}

}  // namespace

std::vector<Fragment> LevelSetBody::fragments(const FragmentSettings& settings, int collisionTriangles,
                                              int minimumPieces) const {
    settings.validate();
    if (collisionTriangles < 4)
        throw Error(impl_->name + ": fragments: collisionTriangles " + std::to_string(collisionTriangles) +
                    " (need >= 4)");
    const Impl& body = *impl_;
    const double dx = body.voxelSize;
    const float background = kHalfWidthVoxels * static_cast<float>(dx);

    // 1. Connected components of the object's interior, dust dropped.
    double dustVolume = 0.0;
    int dustCount = 0;
    std::vector<Component> components = componentsAboveDust(body, settings, dustVolume, dustCount);
    if (static_cast<int>(components.size()) < minimumPieces) return {};

    Int32Grid::Ptr labels = Int32Grid::create(-1);
    {
        auto acc = labels->getAccessor();
        for (int k = 0; k < static_cast<int>(components.size()); ++k)
            for (auto it = components[k].mask->cbeginValueOn(); it; ++it) acc.setValueOn(it.getCoord(), k);
    }
    labelSurfaceShell(*labels, body);

    // 2. Crack voxels with the fragments on either side of their sheet.
    std::vector<CrackVoxel> crackVoxels;
    if (!body.crackTriangles.empty()) {
        auto solidAcc = body.solid->getConstAccessor();
        auto triangleAcc = body.crackTriangle->getConstAccessor();
        auto labelAcc = labels->getConstAccessor();
        auto labelAt = [&](const Eigen::Vector3d& x) { return labelAcc.getValue(nearestVoxel(x, dx)); };
        for (auto it = body.crack->cbeginValueOn(); it; ++it) {
            const Coord ijk = it.getCoord();
            if (!(solidAcc.getValue(ijk) < background)) continue;
            const int t = triangleAcc.getValue(ijk);
            if (t < 0) continue;
            const CrackTriangle& tri = body.crackTriangles[t];
            const Eigen::Vector3d x = voxelCentre(ijk, dx);
            Eigen::Vector3d n = (tri.b - tri.a).cross(tri.c - tri.a);
            if (!(n.norm() > 0.0)) continue;
            n.normalize();
            const Eigen::Vector3d offset = x - closestPointAndFeature(x, tri.a, tri.b, tri.c).point;
            const double s = offset.dot(n) >= 0.0 ? offset.norm() : -offset.norm();
            CrackVoxel v{ijk, s, t, -1, -1};
            for (double probe : kSideProbes)
                if (v.plus < 0) v.plus = labelAt(x + (probe * dx - s) * n);
            for (double probe : kSideProbes)
                if (v.minus < 0) v.minus = labelAt(x - (probe * dx + s) * n);
            if (v.plus >= 0 || v.minus >= 0) crackVoxels.push_back(v);
        }
    }
    std::vector<std::vector<int>> crackVoxelsOf(components.size());
    for (int i = 0; i < static_cast<int>(crackVoxels.size()); ++i) {
        const CrackVoxel& v = crackVoxels[i];
        if (v.plus >= 0) crackVoxelsOf[v.plus].push_back(i);
        if (v.minus >= 0 && v.minus != v.plus) crackVoxelsOf[v.minus].push_back(i);
    }

    // 3. Each fragment's level set, mass, meshes and hull.
    std::vector<Fragment> fragments;
    auto objectAcc = body.object->getConstAccessor();
    auto solidAcc = body.solid->getConstAccessor();
    auto crackAcc = body.crack->getConstAccessor();
    auto labelAcc = labels->getConstAccessor();
    for (int k = 0; k < static_cast<int>(components.size()); ++k) {
        // Narrow band around the component: dilate by the band width plus one voxel.
        openvdb::BoolTree band(components[k].mask->tree());
        serially([&] {
            openvdb::tools::dilateActiveValues(band, static_cast<int>(kHalfWidthVoxels) + 1,
                                               openvdb::tools::NN_FACE_EDGE_VERTEX,
                                               openvdb::tools::IGNORE_TILES);
        });
        FloatGrid::Ptr phi = makeLevelSet(dx);
        auto phiAcc = phi->getAccessor();
        auto assign = [&](const Coord& ijk, float value) {
            if (value >= background) {
                phiAcc.setValueOff(ijk, background);
            } else if (value <= -background) {
                phiAcc.setValueOff(ijk, -background);
            } else {
                phiAcc.setValueOn(ijk, value);
            }
        };
        for (auto it = band.cbeginValueOn(); it; ++it) {
            const Coord ijk = it.getCoord();
            const float o = objectAcc.getValue(ijk);
            const int label = labelAcc.getValue(ijk);
            // In (or beside) another fragment, or in a crack slab: outside this one (crack voxels
            // below refine this). A slab voxel's object distance is below a voxel, so kept as it
            // is it would count as partly inside every fragment whose band reaches it.
            const bool inSlab = crackAcc.getValue(ijk) < 0.0f;
            if (label == k || (label < 0 && o >= 0.0f && !inSlab)) {
                assign(ijk, o);
            } else {
                assign(ijk, background);
            }
        }
        // Crack voxels: surface on the sheet where the crack separates, filled where it ends inside.
        std::set<int> incomplete;
        std::vector<int> filled;
        for (int i : crackVoxelsOf[k]) {
            const CrackVoxel& v = crackVoxels[i];
            // A voxel of another fragment stays its own, although probes past it find this one on
            // both sides (a chip between the sheet and this fragment).
            if (const int own = labelAcc.getValue(v.ijk); own >= 0 && own != k) continue;
            const float solid = solidAcc.getValue(v.ijk);
            if (v.plus == k && v.minus == k) {
                assign(v.ijk, solid);
                filled.push_back(i);
                if (crackAcc.getValue(v.ijk) < 0.0f && solid < 0.0f)
                    incomplete.insert(body.crackTriangles[v.triangle].crackId);
            } else if (v.plus < 0 || v.minus < 0) {  // no fragment on the other side: all of it here
                assign(v.ijk, solid);
                filled.push_back(i);
            } else {
                const double side = v.plus == k ? -v.signedDistance : v.signedDistance;
                assign(v.ijk, std::max(solid, static_cast<float>(side)));
            }
        }
        dropIslands(*phi, *components[k].mask, background);
        if (const int jumps = closeSignJumps(*phi, band); jumps > 0)
            logf(LogLevel::Debug, body.name, "/", fragments.size(), ": ", jumps,
                 " voxel pairs jump from inside to outside; surface put on their shared faces");
        serially([&] { openvdb::tools::pruneLevelSet(phi->tree()); });

        Fragment f;
        f.name = body.name + "/" + std::to_string(fragments.size());
        f.mass = integrateMass(*phi);
        // A piece cannot outweigh its parent beyond the level set's voxel tolerance: more than
        // twice its volume means the cut's sweep left the body (meshing it could exhaust memory).
        if (f.mass.volume > kMaxFragmentToParentVolume * body.mass.volume)
            throw Error(f.name + ": fragment of " + std::to_string(f.mass.volume) + " m^3 from a body of " +
                        std::to_string(body.mass.volume) +
                        " m^3: the crack cut reaches outside the body; fracture abandoned");
        if (!(f.mass.volume > settings.dustMaxFraction * body.originalVolume)) {
            dustVolume += std::max(0.0, f.mass.volume);
            ++dustCount;
            continue;
        }
        f.fractionOfOriginal = f.mass.volume / body.originalVolume;
        f.fractionOfParent = f.mass.volume / body.mass.volume;
        f.volumeClass = classifyFragment(f.mass.volume, body.mass.volume, body.originalVolume, settings);
        f.incompleteCracks.assign(incomplete.begin(), incomplete.end());

        TriangleMesh surface = meshFromGrid(*phi, f.name);
        if (surface.triangles.size() < 4) {  // a flake about a voxel thick: its voxels' hull
            logf(LogLevel::Info, f.name, ": fragment of ", f.mass.volume, " m^3 (", surface.vertices.size(),
                 " surface vertices) is too thin to mesh; its surface is the hull of its voxels");
            surface = voxelHull(*phi, f.name);
        }
        f.collisionMesh = collisionMeshFromGrid(*phi, collisionTriangles, f.name + " (collision)", &surface);
        try {
            f.convexHull = convexHullMesh(surface.vertices, f.name + " (convex hull)");
        } catch (const Error&) {  // a flat sliver
        }
        if (!holdsVolume(f.convexHull, f.mass.volume, f.mass.centreOfMass)) {
            logf(LogLevel::Debug, f.name, ": fragment of ", f.mass.volume,
                 " m^3: its surface's hull does not hold its volume; the hull of its voxels instead");
            f.convexHull = voxelHull(*phi, f.name + " (convex hull)");
        }

        // The fragment as a body of its own, with its incomplete cracks still cut into it.
        auto child = std::make_unique<Impl>();
        child->name = f.name;
        child->voxelSize = dx;
        child->originalVolume = body.originalVolume;
        child->solid = phi;
        // Its crack grid: the narrow band of the incomplete cracks inside it, triangles renumbered.
        child->crack = makeLevelSet(dx);
        child->crackTriangle = Int32Grid::create(-1);
        child->crackTriangle->setTransform(phi->transformPtr());
        {
            auto childCrackAcc = child->crack->getAccessor();
            auto childTriangleAcc = child->crackTriangle->getAccessor();
            std::map<int, int> renumber;
            for (int i : filled)
                if (incomplete.count(body.crackTriangles[crackVoxels[i].triangle].crackId))
                    renumber.emplace(crackVoxels[i].triangle, 0);
            for (auto& [old, fresh] : renumber) {
                fresh = static_cast<int>(child->crackTriangles.size());
                child->crackTriangles.push_back(body.crackTriangles[old]);
            }
            for (int i : filled) {
                const auto it = renumber.find(crackVoxels[i].triangle);
                if (it == renumber.end()) continue;
                childCrackAcc.setValueOn(crackVoxels[i].ijk, crackAcc.getValue(crackVoxels[i].ijk));
                childTriangleAcc.setValueOn(crackVoxels[i].ijk, it->second);
            }
        }
        child->mass = f.mass;
        child->rebuildObject();
        // Carving its incomplete cracks back in can leave single voxels on the sheet where the
        // crack turns from separating to incomplete (phi there is -0.01 voxel): islands too.
        // Without incomplete cracks the object is phi, which has none left.
        if (!incomplete.empty()) dropIslands(*child->object, *components[k].mask, background);
        f.visualMesh = incomplete.empty() ? surface : meshFromGrid(*child->object, f.name + " (visual)");
        if (f.visualMesh.name == f.name) f.visualMesh.name = f.name + " (visual)";
        if (f.volumeClass == FragmentClass::Breakable || f.volumeClass == FragmentClass::KeepsParentSolver) {
            f.surfaceMesh = std::move(surface);
            f.surfaceMesh.name = f.name + " (surface)";
            f.levelSet.reset(new LevelSetBody(std::move(child)));
        }
        fragments.push_back(std::move(f));
    }
    if (dustCount > 0)
        logf(LogLevel::Info, body.name, ": dropped ", dustCount, " dust fragment(s) of ", dustVolume,
             " m^3 in total (<= ", settings.dustMaxFraction, " of the original volume each, or unmeshable)");
    return fragments;
}

}  // namespace btfracture
