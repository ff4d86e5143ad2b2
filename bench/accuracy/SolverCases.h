// SPDX-License-Identifier: Zlib
#pragma once
// The study's cases that run the fracture solver directly on one body (no rigid-body world):
// penny and inclined penny crack (analytic reference, validation.md (a)), the paper's mode-I and
// mode-II growth tests (§6, Figs. 3-5), three-point bending of a pre-cracked and an uncracked bar
// (Fig. 6) and a penny crack growing in a 2,000-triangle cube (the cost scaling of §4.4).
#include "RunResult.h"

#include <btFracture/core/FractureSettings.h>

#include <string>
#include <vector>

namespace accuracy {

struct MethodChoice {
    std::string label;  // FULL, EST, HYB-25, ...
    btfracture::FractureMethod method = btfracture::FractureMethod::Full;
    int threshold = 0;  // HYBRID: surface + crack triangles at which it switches to EST
};

struct SolverCaseInfo {
    std::string name;
    bool grows = false;     // propagation steps (HYBRID differs from FULL and EST only then)
    bool analytic = false;  // reference: closed form (else the FULL run)
};

// The cases in study order; `smoke` keeps only the quick ones (a few seconds in all) and grows
// only over the compared steps.
std::vector<SolverCaseInfo> solverCases(bool smoke);

// One run. Analytic cases set sifError; growth cases leave it to the driver (it compares the
// per-step mean K against the FULL run's: see compareWithReference). `refinement` k >= 1: crack
// elements k times finer than the default (pre-cracks with k times the rings, new front edges
// relative to the mean BEM triangle diameter / k).
RunResult runSolverCase(const std::string& name, const MethodChoice& method, bool smoke, int refinement);

// Relative SIF error of a growth run against the FULL run over the steps both measured: the
// largest |mean K / mean K_FULL - 1| (K_I for the mode-I cases, K_eff otherwise).
double compareWithReference(const std::string& name, const RunResult& run, const RunResult& full);

}  // namespace accuracy
