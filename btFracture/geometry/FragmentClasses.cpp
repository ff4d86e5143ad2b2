// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/FragmentClasses.h>

#include <btFracture/core/Error.h>

#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

void requireSetting(bool ok, const char* field, double value, const char* rule) {
    if (ok) return;
    std::ostringstream msg;
    msg << "fragment settings: " << field << " = " << value << " is invalid; " << rule;
    throw Error(msg.str());
}

}  // namespace

const char* fragmentClassName(FragmentClass c) {
    switch (c) {
        case FragmentClass::ConvexHull:
            return "convex hull";
        case FragmentClass::Unbreakable:
            return "unbreakable mesh";
        case FragmentClass::Breakable:
            return "breakable";
        case FragmentClass::KeepsParentSolver:
            return "keeps parent solver";
    }
    return "?";
}

void FragmentSettings::validate() const {
    requireSetting(std::isfinite(dustMaxFraction) && dustMaxFraction >= 0.0, "dustMaxFraction",
                   dustMaxFraction, "need 0 <= dustMaxFraction < convexHullMaxFraction");
    requireSetting(std::isfinite(convexHullMaxFraction) && convexHullMaxFraction > dustMaxFraction,
                   "convexHullMaxFraction", convexHullMaxFraction,
                   "need dustMaxFraction < convexHullMaxFraction");
    requireSetting(std::isfinite(unbreakableMaxFraction) && unbreakableMaxFraction >= convexHullMaxFraction &&
                       unbreakableMaxFraction < 1.0,
                   "unbreakableMaxFraction", unbreakableMaxFraction,
                   "need convexHullMaxFraction <= unbreakableMaxFraction < 1");
    requireSetting(std::isfinite(keepParentSolverFraction) && keepParentSolverFraction > 0.0 &&
                       keepParentSolverFraction <= 1.0,
                   "keepParentSolverFraction", keepParentSolverFraction,
                   "need 0 < keepParentSolverFraction <= 1");
}

FragmentClass classifyFragment(double volume, double parentVolume, double originalVolume,
                               const FragmentSettings& settings) {
    if (!(volume > 0.0 && parentVolume > 0.0 && originalVolume > 0.0) || !std::isfinite(volume) ||
        !std::isfinite(parentVolume) || !std::isfinite(originalVolume)) {
        std::ostringstream msg;
        msg << "classifyFragment: volumes must be finite and > 0, got fragment " << volume << ", parent "
            << parentVolume << ", original " << originalVolume << " m^3";
        throw Error(msg.str());
    }
    const double ofOriginal = volume / originalVolume;
    if (ofOriginal <= settings.convexHullMaxFraction) return FragmentClass::ConvexHull;
    if (ofOriginal <= settings.unbreakableMaxFraction) return FragmentClass::Unbreakable;
    if (volume > settings.keepParentSolverFraction * parentVolume) return FragmentClass::KeepsParentSolver;
    return FragmentClass::Breakable;
}

}  // namespace btfracture
