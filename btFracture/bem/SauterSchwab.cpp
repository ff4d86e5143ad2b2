// SPDX-License-Identifier: Zlib
#include <btFracture/bem/SauterSchwab.h>

#include <btFracture/core/Error.h>

#include <string>

namespace btfracture {
namespace {

constexpr int kMaxPoints = 12;

SauterSchwabRule tabulate(PairRelation relation, int n, bool swapSymmetric) {
    SauterSchwabRule rule;
    int index = 0;
    forEachSauterSchwabPoint(relation, n, [&](double x1, double x2, double y1, double y2, double w) {
        // Identical panels visit each point pair and its swap consecutively: keep the first.
        if (swapSymmetric) {
            if (index++ % 2 == 1) return;
            w *= 2.0;
        }
        rule.points.push_back({x1, x2, y1, y2, w});
    });
    return rule;
}

}  // namespace

const SauterSchwabRule& sauterSchwabRule(PairRelation relation, int n, bool swapSymmetric) {
    if (n < 1 || n > kMaxPoints || relation == PairRelation::Separated)
        throw Error("Sauter-Schwab rule with " + std::to_string(n) +
                    " points per axis requested; supported: 1.." + std::to_string(kMaxPoints) +
                    " for singular pairs");
    // [relation][swapSymmetric][n]
    static const auto tables = [] {
        std::array<std::array<std::array<SauterSchwabRule, kMaxPoints + 1>, 2>, 3> all;
        for (int r = 0; r < 3; ++r)
            for (int k = 1; k <= kMaxPoints; ++k) {
                all[r][0][k] = tabulate(static_cast<PairRelation>(r), k, false);
                if (r == static_cast<int>(PairRelation::Identical))
                    all[r][1][k] = tabulate(PairRelation::Identical, k, true);
            }
        return all;
    }();
    const bool merge = swapSymmetric && relation == PairRelation::Identical;
    return tables[static_cast<int>(relation)][merge ? 1 : 0][n];
}

}  // namespace btfracture
