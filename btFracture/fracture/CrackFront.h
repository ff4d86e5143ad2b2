// SPDX-License-Identifier: Zlib
#pragma once
// The high-resolution crack front (paper §3: "we propagate the crack-front at high resolution";
// Hahn & Wojtan 2015 §5): per crack sheet, ordered marker polylines about one voxel apart that
// lead the coarse BEM front. Each marker moves by the advance (distance x direction)
// interpolated along the coarse front edge nearest to it, in sub-steps of at most half a
// voxel; a coarse node whose markers all stopped stops level with them (advance():
// coarseTargets). Markers are inserted and removed to keep neighbours 0.5 to 2 spacings apart,
// the per-marker steps are lightly smoothed. A marker meeting the surface slides along it where
// the coarse front would (SurfaceSlide.h: the ends of a through crack run along a thin body's
// faces; the crack plane from its coarse front edge, FrontMarker::coarseTangent), else it stops
// for good there; it also stops when it enters a crack already cut into it
// (a marker outside the body since it was made, on a seed poking through the surface, follows the
// coarse front freely until it enters the body). Sheets growing together (one event) pass
// through each other as the coarse BEM sheets do
// (CrackGrowth.h: only a coarse node crossing a coarse triangle stops): their markers stop at
// another sheet's swept surface only when extend() carries a stopped coarse front on to its
// obstacle. Stopping them at every close pass turned the coarse sheets' crossings into
// T-junctions that leave the glass slab of tests/coupling in one piece. The
// swept surface between successive polylines is kept as triangles for the caller to cut into
// the level set (LevelSetBody::cutAlongSurface).
//
// No OpenVDB, no Bullet: the body is seen through FrontQueries. Units: metres; the frame is the
// caller's (the level set's frame in the engine).
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace btfracture {

// What the front needs to know about the body.
struct FrontQueries {
    std::function<bool(const Eigen::Vector3d&)> insideBody;  // inside the uncut solid
    std::function<int(const Eigen::Vector3d&)> crackAt;      // id of the crack slab at p, -1 if none
    // Outward unit normal of the uncut solid's surface near p; without it markers never slide.
    std::function<Eigen::Vector3d(const Eigen::Vector3d&)> surfaceNormal;
};

// One coarse (BEM) front of a sheet for one step.
struct CoarseFront {
    std::map<int, Eigen::Vector3d> position;  // coarse node id -> position [m]
    std::map<int, Eigen::Vector3d> advance;   // coarse node id -> distance x direction [m]; missing = 0
    std::vector<std::pair<int, int>> edges;   // front edges a -> b (interior on the left)
};

struct FrontMarker {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();   // [m]
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit direction of its last move (0: never moved)
    bool arrested = false;  // left the body or met another crack: never moves again
    bool free = false;      // outside the body since it was made (a seed poking through the surface)
    int home = -1;          // crack slab it started in (an id it may leave without stopping)
    int coarseNode = -1;    // nearest coarse front node (arrest feedback)
    // Tangent of the nearest coarse front edge in the last advance (before any: of the edge the
    // marker was made on; 0 on a zero-length edge, where it cannot slide): the crack plane a
    // sliding marker keeps (SurfaceSlide), smooth where the marker polyline is not.
    Eigen::Vector3d coarseTangent = Eigen::Vector3d::Zero();
};

struct MarkerChain {
    std::vector<FrontMarker> markers;
    bool closed = true;  // a loop; else an open chain
};

struct FrontAdvanceResult {
    int substeps = 0;
    int arrestedMarkers = 0;            // newly arrested, of which:
    int leftBody = 0;                   //   at the body's surface
    int metCrack = 0;                   //   in a crack already cut (FrontQueries::crackAt)
    int metSheet = 0;                   //   at another sheet's swept surface (extend() only)
    int slid = 0;                       // markers that met the surface and slid along it (SurfaceSlide.h)
    std::set<int> arrestedCoarseNodes;  // coarse nodes that once moved and whose markers all stopped
    // advance() only: per coarse node that was to move, the point of its markers' polyline
    // closest to its aim, position + advance [m, the caller's frame]: near the aim where the
    // markers followed the coarse front, short of or beside it where they stopped at or slid
    // along the level set's surface. The engine ends a stopped node's step level with it.
    std::map<int, Eigen::Vector3d> coarseTargets;
    double largestTargetShift = 0.0;  // max |target - aim| [m]
};

class CrackFronts {
public:
    // `spacing`: target marker spacing [m] (one voxel). Throws btfracture::Error unless finite and > 0.
    explicit CrackFronts(double spacing);

    double spacing() const { return spacing_; }
    bool hasSheet(int sheet) const { return sheets_.count(sheet) > 0; }
    // Markers along the coarse front edges of a new sheet, at most one spacing apart: one closed
    // chain per loop of edges (an open chain where the edges do not close). Throws
    // btfracture::Error if the sheet already has markers or an edge's node has no position.
    void addSheet(int sheet, const CoarseFront& front, const FrontQueries& queries);
    // Adds triangles (e.g. a new sheet's coarse seed) to the swept surface of `sheet`: they are
    // returned by takeSwept() and stop other sheets' markers in extend() like swept triangles do.
    void addSurface(int sheet, const TriangleMesh& triangles);
    const std::vector<MarkerChain>& chains(int sheet) const;
    std::vector<int> sheets() const;

    // One coarse step for every sheet in `fronts` (sheets without markers are ignored): each marker
    // moves by the advance interpolated along its sheet's nearest coarse front edge, stopping at
    // the surface and in cut cracks, not at other sheets' swept surfaces. Returns where the
    // moved markers put each coarse node (FrontAdvanceResult::coarseTargets).
    FrontAdvanceResult advance(const std::map<int, CoarseFront>& fronts, const FrontQueries& queries);
    // Moves the still active markers whose coarse node is in `stoppedNodes[sheet]` up to
    // `distance` [m] further along their last direction, then stops them for good (the coarse
    // front stopped at an obstacle of the coarse BEM mesh, which can lie short of the level
    // set's: carry the cut up to the real one). Here markers also stop at other sheets' swept
    // surfaces (within 0.85 spacing, the slab half-width), fronts extended together at each
    // other's sub-step strips.
    FrontAdvanceResult extend(const std::map<int, std::set<int>>& stoppedNodes, double distance,
                              const FrontQueries& queries);

    // After the body lost material (§5.3: a fragment keeps the parent's fronts), active markers
    // now outside it follow the coarse front freely until they enter the body again, like
    // markers made outside. Returns how many were freed.
    int freeOutside(const FrontQueries& queries);

    // The fronts of the sheets in `newSheetOf` for a fragment that carries them as incomplete
    // cracks (§5.3: the sheets and their front data are copied): markers keep their state, sheet
    // ids (also the markers' home crack) become newSheetOf[old] and coarse node ids
    // newNodeOf[old] (-1 where missing). Swept triangles are not copied: they are cut already.
    CrackFronts extractSheets(const std::map<int, int>& newSheetOf,
                              const std::map<int, int>& newNodeOf) const;

    // Triangles swept since the last call, per sheet (triangle soups), and forgets them.
    std::map<int, TriangleMesh> takeSwept();
    int sweptTriangles() const;

private:
    using Cells = std::unordered_map<std::int64_t, std::vector<std::pair<int, std::vector<int>>>>;
    using Strip = std::pair<Eigen::Vector3d, Eigen::Vector3d>;  // where a chain edge's strip began
    using Strips = std::vector<Strip>;
    FrontAdvanceResult sweep(std::map<int, std::vector<std::vector<Eigen::Vector3d>>>& steps,
                             const FrontQueries& queries, bool stopAtSheets);
    void resample(int sheet, MarkerChain& chain, std::vector<Eigen::Vector3d>& steps, Strips& from);
    void readCoarseTargets(int sheet, const CoarseFront& front, FrontAdvanceResult& result) const;
    void emitStrip(int sheet, const MarkerChain& chain, const Strips& from, std::size_t edge);
    bool nearOtherSheet(int sheet, const Eigen::Vector3d& p) const;
    void addTriangle(std::map<int, TriangleMesh>& store, Cells& cells, int sheet, const Eigen::Vector3d& a,
                     const Eigen::Vector3d& b, const Eigen::Vector3d& c);

    double spacing_;
    std::map<int, std::vector<MarkerChain>> sheets_;
    // Per sheet: coarse nodes that ever drove a moving marker (only those are reported arrested).
    std::map<int, std::set<int>> movedCoarseNodes_;
    // Swept triangles per sheet and their spatial hash (cells of 2 spacings: cell key -> per
    // sheet, its triangles); the transient pair holds the sub-step strips of one advance.
    std::map<int, TriangleMesh> swept_, transient_;
    Cells cells_, transientCells_;
};

}  // namespace btfracture
