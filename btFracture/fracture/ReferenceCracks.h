// SPDX-License-Identifier: Zlib
#pragma once
// Reference crack problems shared by the tests (tests/crack) and the benchmarks (bench/accuracy,
// bench/sif_validation): the penny and inclined penny crack with their closed forms (Kassir &
// Sih, validation.md (a)), the surface-breaking edge crack and notched beam with their handbook
// forms, and the pre-cracked slab of the paper's mode-I / mode-II growth tests (§6, Figs. 3-5).
// Units: SI.
#include <btFracture/bem/CrackMesh.h>
#include <btFracture/bem/SurfaceMesh.h>
#include <btFracture/core/FractureSettings.h>
#include <btFracture/core/Material.h>
#include <btFracture/core/TriangleMesh.h>
#include <btFracture/fracture/StressIntensity.h>

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

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

// The penny-crack body: a cube of side 8 a (`cells` x `cells` squares per face, edge 8 a / cells),
// large enough that the free surface changes K_I by about 1 %.
TriangleMesh pennyCrackCube(double radius, int cells = 6);

// Surface-breaking through cracks: a planar sheet from the body's surface to a straight front
// across the whole thickness, poking `extension` elements past the surface (0: ending on it).
// K_I is read at the front node nearest mid-thickness.
struct SurfaceCrackCase {
    std::string name;
    TriangleMesh body;  // in the case's own coordinates
    // The sheet: origin + u U + v V for every u in `along` (depth, the front at the last) and v in
    // `across`, crack normal U x V; own coordinates.
    Eigen::Vector3d origin, U, V;
    std::vector<double> along, across;
    Eigen::Vector3d midFront;  // own coordinates
    std::function<Eigen::VectorXd(const SurfaceMesh&)> tractions;
    double exactKI = 0.0;  // [Pa m^(1/2)]
};

// The edge-crack plate's width b and thickness [m] (as thick as wide: its mid-thickness is near
// plane strain, which the handbook value assumes) and tension sigma [Pa].
constexpr double kEdgeCrackPlateWidth = 0.1, kEdgeCrackPlateThickness = kEdgeCrackPlateWidth,
                 kEdgeCrackTension = 1e6;
// Plate of width b = kEdgeCrackPlateWidth (x), height 4 b (y) and thickness b (z) under uniform
// tension sigma = kEdgeCrackTension along y, straight edge crack of depth a = ratio b from the
// face x = 0; h = a / elementsPerDepth on the surface near the crack, h / crackRefinement on the
// crack (the mouth then has sheet nodes inside surface edges). Exact: sigma sqrt(pi a) F(a/b)
// (Tada's fit, 0.5 % for a/b <= 0.6; edgeCrackFactor).
SurfaceCrackCase edgeCrackCase(double ratio, int elementsPerDepth, double extension = 0.0,
                               int crackRefinement = 1);
// ASTM E399 single-edge-notched beam in three-point bending: depth W (y), span S = 4 W, thickness
// B = W/2, a/W = 0.5, load P on a patch of the top face over the crack, P/2 on a patch over each
// support; h = a / elementsPerDepth near the crack. Exact: P S / (B W^1.5) f(a/W).
SurfaceCrackCase notchedBeamCase(int elementsPerDepth, double extension = 0.0);

// K_I / sigma = F(a/b) sqrt(pi a) of an edge crack of depth a in a plate of width b under
// tension sigma (Tada's fit) [m^(1/2)].
double edgeCrackFactor(double a, double b);

// Adds the case's sheet to `cracks`, in the frame of `body` (the case's body; its offset taken off).
void addSurfaceCrackSheet(CrackMesh& cracks, const SurfaceCrackCase& c, const SurfaceMesh& body);
// Of the SIFs `sifs` of the case's sheet in `body`'s frame (grown or not), the front node
// nearest mid-thickness (across coordinate 0).
const FrontSifs& midThicknessSifs(const std::vector<FrontSifs>& sifs, const SurfaceCrackCase& c,
                                  const SurfaceMesh& body);

// Semicircular surface crack of radius a = 2 cm, `rings` rings (addHalfDiscCrack), from the face
// x = 0 of a plate t = 4 a thick (x), 8 a wide (z) and 16 a high (y) under uniform tension sigma =
// kEdgeCrackTension along y; surface elements of a / rings near the crack. K_I at the deepest
// front node against Newman & Raju (1981) for a/c = 1, a/t = 0.25, c/b = 0.25 (their fit is
// within about 5 % of their finite-element values): 0.677 sigma sqrt(pi a).
struct SemicircularCrackResult {
    double deepestKI = 0.0, exactKI = 0.0;  // [Pa m^(1/2)]
    double surfaceKI = 0.0;  // at the front node nearest the face (not fitted there: reported only)
    int surfaceTriangles = 0, crackUnknowns = 0, mouthNodes = 0;
};
SemicircularCrackResult solveSemicircularCrack(int rings, const Material& material);
double newmanRajuDeepestFactor(double aOverT, double cOverB);  // K_I / (sigma sqrt(pi a)), a = c

struct SurfaceCrackResult {
    // At the front node nearest mid-thickness: FULL (Eq. 4, displacement correlation) and EST
    // (§4.2 from the crack-free local stress, as at the start of an event: no front has moved).
    double KI = 0.0, estimatedKI = 0.0;
    int surfaceTriangles = 0, crackUnknowns = 0;
};
SurfaceCrackResult solveSurfaceCrack(const SurfaceCrackCase& c, const Material& material);

// The growth tests: a 20 x 10 x 6 cm slab (360 triangles), PMMA-like stiffness with high
// strength (no new seeds) and tiny toughness (every front node grows), a disc pre-crack of
// `rings` rings (2 by default) and radius 1.2 cm, normal x, 2 cm above the centre (offset along
// y), grown with full-length steps (minimum speed 1) and front edges of 0.6 h.
TriangleMesh growthSlab();
// The embedded-growth block: 20 x 26 x 26 cm with the slab's 2 cm elements (1,716 triangles). A
// pre-crack at its centre (offset 0) stays embedded for kEmbeddedGrowthSteps full-length steps,
// its radius below the ligament to the surface: where EST, which treats every crack as embedded,
// is compared with FULL, whose cracks open where they reach the surface.
TriangleMesh embeddedGrowthBlock();
constexpr int kEmbeddedGrowthSteps = 4;
Material growthMaterial();
FractureSettings growthSettings(FractureMethod method);
void addGrowthPreCrack(CrackMesh& cracks, double offsetY = 0.03, int rings = 2);
// Far-field stress of the nominally mode-I (tension along x, normal to the pre-crack) and
// mode-II (shear xy, parallel to it) tests [Pa].
Eigen::Matrix3d modeOneStress();
Eigen::Matrix3d modeTwoStress();

}  // namespace btfracture
