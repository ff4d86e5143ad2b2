// SPDX-License-Identifier: Zlib
#pragma once
// Reference crack problems shared by the tests (tests/crack) and the accuracy study
// (bench/accuracy): the penny and inclined penny crack with their closed forms (Kassir & Sih,
// validation.md (a)), and the pre-cracked slab of the paper's mode-I / mode-II growth tests
// (§6, Figs. 3-5). Units: SI.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/SurfaceMesh.h>
#include <btFracture/core/FractureSettings.h>
#include <btFracture/core/Material.h>
#include <btFracture/core/TriangleMesh.h>

#include <Eigen/Core>

namespace btfracture {

// P0 tractions sigma n on every surface triangle (3 per triangle) [Pa].
Eigen::VectorXd uniformStressTractions(const SurfaceMesh& mesh, const Eigen::Matrix3d& sigma);

// Penny crack of radius a under uniaxial tension s whose direction makes the angle alpha with
// the crack plane (alpha = pi/2: normal to it). K_I is constant along the front; K_II and K_III
// vary as cos(w) and sin(w) of the front angle w measured from the in-plane load direction, with
// the amplitudes below [Pa m^(1/2)].
struct PennyCrackSifs {
    double KI = 0.0, KIIAmplitude = 0.0, KIIIAmplitude = 0.0;
};
PennyCrackSifs pennyCrackSifs(double stress, double radius, double alpha, double poissonRatio);

// The penny-crack body: a cube of side 8 a (6 x 6 cells per face), large enough that the free
// surface changes K_I by about 1 %.
TriangleMesh pennyCrackCube(double radius);

// The growth tests: a 20 x 10 x 6 cm slab (360 triangles), PMMA-like stiffness with high
// strength (no new seeds) and tiny toughness (every front node grows), a two-ring disc pre-crack
// of radius 1.2 cm, normal x, 2 cm above the centre (offset along y), grown with full-length
// steps (minimum speed 1) and front edges of 0.6 h.
TriangleMesh growthSlab();
Material growthMaterial();
FractureSettings growthSettings(FractureMethod method);
void addGrowthPreCrack(CrackMesh& cracks, double offsetY = 0.03);
// Far-field stress of the nominally mode-I (tension along x, normal to the pre-crack) and
// mode-II (shear xy, parallel to it) tests [Pa].
Eigen::Matrix3d modeOneStress();
Eigen::Matrix3d modeTwoStress();

}  // namespace btfracture
