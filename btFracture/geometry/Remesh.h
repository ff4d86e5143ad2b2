// SPDX-License-Identifier: Zlib
#pragma once
// The BEM mesh: a closed surface mesh with a chosen number of well-shaped triangles that
// approximates a (usually much finer) input surface. The boundary element solver works on it
// (paper §3: the coarsest of the three resolutions), so triangle shape matters more than
// reproducing sharp features exactly.
//
// Method: isotropic remeshing (Botsch & Kobbelt 2004) towards the edge length L of an
// equilateral triangle with area A / targetTriangles (A = sqrt(3)/4 L^2): split edges longer
// than 4/3 L, collapse edges shorter than 4/5 L, flip edges towards valence 6, relax vertices
// tangentially, project them onto the input surface; L is corrected every iteration so the
// triangle count meets the target. Where the input is thin and bends (a wall's rim, a handle)
// and a uniform L leaves the two sides of a thin part intersecting, the target length is
// shorter than L there and grades back to L (ThicknessSizing.h), without small elements
// everywhere. A repair pass then removes the triangles that are still below the angle bound
// (QualityRepair.h). Sharp edges and corners of the input are not tracked: they end up rounded
// over a width of about the local target length.
#include <btFracture/core/TriangleMesh.h>

namespace btfracture {

struct RemeshOptions {
    int iterations = 15;            // isotropic remeshing iterations, >= 1
    double minAngleDegrees = 20.0;  // every output angle should reach this, in (0, 35]
    int repairPasses = 30;          // sweeps of the quality repair, >= 0
    double smoothingStep = 0.5;     // tangential relaxation factor per iteration, in (0, 1]
    // Finally move vertices along their normals so that the mesh straddles the input surface
    // instead of lying inside it where it is convex (SurfaceFit.h); keeps the volume.
    bool fitAcrossSurface = true;
    // Rounds that halve the target edge length around triangles that smoothing could not
    // separate, >= 0; each costs a few remeshing iterations over the whole mesh.
    int maxRefinements = 3;
    // Shorter edges where the input is thin and bends (ThicknessSizing.h): never, only when a
    // uniform mesh intersects itself (the default: meshes a uniform L serves stay as they were),
    // or always first.
    enum class ThicknessSizing { Never, WhenUniformFails, Always };
    ThicknessSizing thicknessSizing = ThicknessSizing::WhenUniformFails;
    // Wall-clock limit [s] for the whole remesh, > 0; checked between iterations and passes.
    double timeBudgetSeconds = 60.0;
};

// Remeshes a closed, manifold, consistently oriented triangle mesh (core/MeshCheck.h) to about
// targetTriangles triangles (within a few percent) with all angles >= options.minAngleDegrees.
// Where that mesh still intersects itself and the input has thin parts, a mesh with shorter
// edges there (within the target) is tried, and then one with the thin parts' own edge lengths,
// whose count exceeds the target (the teapot's walls, 0.9 % of its size: about 4,800 triangles
// for a target of 1,000); options.thicknessSizing sets the order.
// Triangles that no local edit could bring up to the bound are reported in a warning (Log.h);
// measureQuality() (MeshQuality.h) tells callers what they got. The output is closed, manifold,
// oriented like the input, lies on the input surface up to the repair pass's relaxations, and
// has the input's genus. Deterministic.
// Throws btfracture::Error naming input.name for an input that is not a closed manifold, a
// target below 20 triangles, options out of range, or a remesh that outlasts
// options.timeBudgetSeconds.
TriangleMesh remeshForBem(const TriangleMesh& input, int targetTriangles, const RemeshOptions& options = {});

}  // namespace btfracture
