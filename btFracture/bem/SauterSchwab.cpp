// SPDX-License-Identifier: Zlib
#include <btFracture/bem/SauterSchwab.h>

#include <btFracture/core/Error.h>

#include <array>
#include <mutex>
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
    // [relation][swapSymmetric][n], each tabulated at its first use: all twelve sizes of the three
    // relations hold about 40 MB, and a solver asks for two or three of them.
    static std::array<std::array<std::array<SauterSchwabRule, kMaxPoints + 1>, 2>, 3> tables;
    static std::array<std::array<std::array<std::once_flag, kMaxPoints + 1>, 2>, 3> tabulated;
    const bool merge = swapSymmetric && relation == PairRelation::Identical;
    const int r = static_cast<int>(relation), m = merge ? 1 : 0;
    std::call_once(tabulated[r][m][n], [&] { tables[r][m][n] = tabulate(relation, n, merge); });
    return tables[r][m][n];
}

}  // namespace btfracture
