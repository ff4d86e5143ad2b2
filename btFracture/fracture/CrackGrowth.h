// SPDX-License-Identifier: Zlib
#pragma once
// Advancing crack fronts on the BEM crack mesh itself (the coarse sheet; with voxel-resolution
// markers, FractureSolver first shortens the step of a node whose markers all stopped to end
// level with them): every moving front node gets a new node ahead of it, every front edge a
// strip of new triangles, and over-long new front edges are split (a midpoint outside the body
// moves to just inside it, or onto the surface between two nodes on it; a front node outside it
// never moves). A front node that
// would cross another crack stops there and is arrested for good; one that would leave the body
// stops just inside it and slides along the surface as far as its crack plane allows (the ends of
// a through crack run along the faces), and is arrested when no slide is left. With the fold
// guard, a node whose new triangles would fold back over the sheet (a step behind its front edge,
// neighbours crossing) stays where it is for that step.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/SurfaceMesh.h>
#include <btFracture/fracture/PropagationLaw.h>

#include <map>
#include <vector>

namespace btfracture {

struct GrowthResult {
    int advancedNodes = 0;
    int newTriangles = 0;
    int arrestedNodes = 0;           // newly arrested in this step
    int heldNodes = 0;               // not moved in this step: their strip would fold the sheet
    std::map<int, double> advanced;  // old front node -> distance it moved [m]
    std::map<int, int> newNode;      // old front node -> the node it moved to
};

// Whether nodes whose strip would fold the sheet are held (see above). FULL needs it: a folded
// sheet makes its Schur complement indefinite. EST grows as the steps say.
enum class FoldGuard { Hold, Off };
// Where a front that meets the surface stops. Inside: just inside it (0.9 of the way), as EST's
// embedded-crack estimate needs. OnSurface: on it (FULL, whose sheets open there as mouths,
// FORMULATION.md); a step ending within 0.05 max edge of the surface it heads for ends on it, and
// a node that close goes on to it however short the step, so no front stays shut a sliver inside.
enum class SurfaceReach { Inside, OnSurface };

// `advances[node]` holds the motion of each front node (distance 0 = stays). `arrested` (per
// crack node, grown as needed) marks nodes that never move again. New front edges longer than
// `maxEdge` [m] are split.
GrowthResult growFronts(CrackMesh& cracks, const std::map<int, FrontAdvance>& advances,
                        const SurfaceMesh& body, double maxEdge, std::vector<char>& arrested,
                        FoldGuard guard = FoldGuard::Hold, SurfaceReach reach = SurfaceReach::Inside);

}  // namespace btfracture
