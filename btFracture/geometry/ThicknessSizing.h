// SPDX-License-Identifier: Zlib
#pragma once
// Where a surface needs edges shorter than a remesh's base length L: thin parts that bend. Two
// facing sheets of a wall of thickness T (or two parts a gap T apart), each meshed with chords
// of length h on a surface of curvature radius R, move towards each other by the chords' sag
// h^2 / (8 R) (Dunyach et al. 2013); they stay apart when the sag is at most a fraction tau of
// T, i.e. h <= sqrt(8 tau T R). A flat thin pane (R infinite) keeps long edges on its faces and
// gets short ones along its rim, where the surface turns through 180 degrees within T; a body
// thicker than L gets none.
//
// The surface is sampled every L / 3 (sub-triangle centroids, with the triangle's normal). At a
// sample p with normal n: T is the distance to the closest point of the surface that faces
// the other way (normal within 60 degrees of -n) when that point lies behind p (the wall's
// other side; a gap between two parts is left to the remesher's local refinement);
// R = min |p - q| / (2 sin(theta / 2)) over the samples q between L / 2 and L away whose normal
// makes an angle theta in (10, 120) degrees with n: the curvature at the scale of the elements
// (exact on a sphere; bumps smaller than L / 2 do not count; at a sharp edge, about L / 2, so
// the rim of a 6 mm pane meshed with L = 20 mm gets edges of about 1.5 times its thickness).
#include <btFracture/geometry/ClosestPointTree.h>
#include <btFracture/geometry/EdgeLengthField.h>

#include <vector>

namespace btfracture {

struct ThicknessSizingOptions {
    double sagFraction = 0.5;     // tau: largest chord sag as a fraction of the local thickness
    double smallestFactor = 0.2;  // no site asks for less than this times L
};

// Sizing sites (EdgeLengthField::setSites, referenceBase = baseLength) of `surface`'s mesh
// for a remesh with base edge length `baseLength`: one per cell of size L / 4 that holds
// samples asking for less than 0.9 L, with the smallest length asked for there. Deterministic.
std::vector<SizingSite> thicknessSizingSites(const ClosestPointTree& surface, double baseLength,
                                             const ThicknessSizingOptions& options = {});

}  // namespace btfracture
