// SPDX-License-Identifier: Zlib
#pragma once
// Crack initiation (paper §3, Hahn & Wojtan 2015): where the largest principal surface stress
// exceeds the local tensile strength, or the most negative exceeds compressive factor x
// strength, a small hexagonal crack is seeded perpendicular to that principal direction, just
// under the surface and reaching inwards.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/SurfaceMesh.h>
#include <btFracture/core/FractureSettings.h>
#include <btFracture/fracture/MaterialField.h>

#include <Eigen/Core>

#include <vector>

namespace btfracture {

struct SeedCandidate {
    int triangle = -1;
    double excess = 0.0;          // principal stress / its strength, > 1
    Eigen::Vector3d crackNormal;  // principal direction (unit)
    bool compressive = false;
};

// Triangles whose principal stress exceeds the strength, most overloaded first. Skips
// triangles in `blocked` and those closer to an existing front node than their longest edge.
std::vector<SeedCandidate> findSeedCandidates(const SurfaceMesh& mesh,
                                              const std::vector<Eigen::Matrix3d>& stresses,
                                              const MaterialField& field, const CrackMesh& cracks,
                                              const std::vector<char>& blocked);

// Where a seed sits: inside the body next to the surface (a hexagon whose corner points at the
// surface point; EST, which treats every crack as embedded), or on the surface (half a hexagon
// whose diameter runs through the surface point along the surface, its mouth: FULL, whose mouths
// open, FORMULATION.md "Mouth").
enum class SeedShape { Embedded, SurfaceBreaking };

// Adds up to `maxSeeds` seeds for the candidates (circumradius seedRadius x h, h the crack element
// size `elementSize` [m], or the triangle's diameter where it is 0); a seed that would poke out of
// the body (near an edge, in a thin wall) or whose mouth would leave a curved surface by more than
// kSeedMouthSag of its radius is halved, at most twice. A candidate whose crack plane is nearly
// parallel to the surface, or whose quarter-size seed still does not fit, is skipped with a log
// line. Seeds of one event keep the distance rule among themselves too. Marks seeded triangles in
// `blocked`. Returns the number of seeds.
constexpr double kSeedMouthSag = 0.25;
int seedCracks(CrackMesh& cracks, const SurfaceMesh& mesh, const std::vector<SeedCandidate>& candidates,
               int maxSeeds, double seedRadius, double elementSize, SeedShape shape,
               std::vector<char>& blocked);

}  // namespace btfracture
