#pragma once
// The study's rigid-body cases: the bunny of demos/scenes/bunny_smash.json hit by the steel ball
// (paper Fig. 7) at several BEM resolutions, and the same scene with a weaker bunny for many
// fragments (Fig. 8). Only the bunny breaks (refracture depth 0), so each run has one event.
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

// One run of `frames` frames (4 ms each). Times: the engine's own split for the breaking call,
// whole-step wall time for calls that broke nothing, the rest of the stepping as rigid-body time.
// The fracture surface is the fragments' faces that lie off the bunny's surface (world frame).
RunResult runSceneCase(const SceneCaseInfo& info, const MethodChoice& method, int frames);

}  // namespace accuracy
