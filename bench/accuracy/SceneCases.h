// SPDX-License-Identifier: Zlib
#pragma once
// The study's rigid-body cases: the bunny of demos/scenes/bunny_smash.json hit by the steel ball
// (paper Fig. 7) at several BEM resolutions, and the same scene with a weaker bunny for many
// fragments (Fig. 8). Fragments do not break again (refracture depth 0), but a piece of more than
// 95 % of the bunny continues it (§5.2 (d)) and may break in later events: times sum every event,
// the pattern compared (crack triangles, fragments, surface) is the first event's.
#include "RunResult.h"
#include "SolverCases.h"

#include <string>
#include <vector>

namespace accuracy {

struct SceneCaseInfo {
    std::string name;
    int bemTriangles = 1000;  // BEM surface target of the bunny
    bool weak = false;        // the many-fragment variant
    bool hybrids = true;      // also run HYBRID at three thresholds
};

std::vector<SceneCaseInfo> sceneCases(bool smoke);

// One run of `frames` frames (4 ms each). Times: the engine's own split for the breaking calls,
// whole-step wall time for calls that broke nothing, the rest of the stepping as rigid-body time.
// The fracture surface is the fragments' faces that lie off the bunny's surface (world frame).
// `gainLimit` >= 0 replaces FractureSettings::estimatorUpdateGainLimit (0: off); < 0 keeps it.
RunResult runSceneCase(const SceneCaseInfo& info, const MethodChoice& method, int frames, double gainLimit);

}  // namespace accuracy
