// SPDX-License-Identifier: Zlib
#pragma once
// The volume classes of paper §5.2: what becomes of a piece of a broken body, by its volume.
// "Original" is the volume of the body before its first fracture, passed from parent to
// fragments; "parent" is the body that has just broken. Volumes [m^3].
namespace btfracture {

enum class FragmentClass {
    ConvexHull,         // (a) <= convexHullMaxFraction of the original: convex hull, never breaks
    Unbreakable,        // (b) <= unbreakableMaxFraction of the original: (non-convex) mesh, never breaks
    Breakable,          // (c) larger: collision mesh plus a new BEM, breaks again (§5.3)
    KeepsParentSolver,  // (d) breakable and > keepParentSolverFraction of the parent: reuses its BEM
};

const char* fragmentClassName(FragmentClass c);

// BemFractureEngineSettings::fragments.
struct FragmentSettings {
    double convexHullMaxFraction = 0.005;    // of the original volume (§5.2: 0.5 %)
    double unbreakableMaxFraction = 0.02;    // of the original volume (§5.2: 2 %)
    double keepParentSolverFraction = 0.95;  // of the parent's volume (§5.2: 95 %)
    // Pieces smaller than this fraction of the original volume are dropped (logged): they are a
    // few voxels at most and cannot be meshed (FractureRB uses 1e-6 too).
    double dustMaxFraction = 1e-6;

    // Throws btfracture::Error naming the field and value unless
    // 0 <= dust < convexHull <= unbreakable < 1 and 0 < keepParentSolver <= 1.
    void validate() const;
};

// Class of a fragment of volume `volume` from a parent of volume `parentVolume`, both pieces of
// a body whose original volume is `originalVolume` (all [m^3], > 0). Thresholds are inclusive
// upper bounds; (d) applies only to fragments that would otherwise be Breakable.
FragmentClass classifyFragment(double volume, double parentVolume, double originalVolume,
                               const FragmentSettings& settings);

}  // namespace btfracture
