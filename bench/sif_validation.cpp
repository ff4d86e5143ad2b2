// SPDX-License-Identifier: Zlib
// FULL stress intensity factors against closed-form and handbook solutions: one line per case
// with its mesh size and K_I, then `METRIC <case> <relative error> ratio`. A case is a name and a
// function returning the relative error; add one to `cases` below.
#include <btFracture/fracture/ReferenceCracks.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

const Material kMaterial(1e9, 0.3, 1000.0, 1e7, 1e6, 2.0, "validation");
// Elements along the crack depth, as in tests/crack (a few seconds per case).
constexpr int kEdgeCrackElements = 4, kNotchedBeamElements = 8;

// K_I at mid-thickness of a surface-breaking through crack, relative to the handbook value.
double surfaceCrackError(const SurfaceCrackCase& c) {
    const SurfaceCrackResult r = solveSurfaceCrack(c, kMaterial);
    std::printf("%s: %d surface triangles, %d crack unknowns, K_I %.5g (exact %.5g)\n", c.name.c_str(),
                r.surfaceTriangles, r.crackUnknowns, r.KI, c.exactKI);
    return std::abs(r.KI / c.exactKI - 1.0);
}

struct Case {
    std::string metric;
    std::function<double()> error;
};

}  // namespace

int main() {
    const std::vector<Case> cases = {
        {"edge_crack_error_0p2", [] { return surfaceCrackError(edgeCrackCase(0.2, kEdgeCrackElements)); }},
        {"edge_crack_error_0p4", [] { return surfaceCrackError(edgeCrackCase(0.4, kEdgeCrackElements)); }},
        {"senb_error", [] { return surfaceCrackError(notchedBeamCase(kNotchedBeamElements)); }},
    };
    for (const Case& c : cases) {
        const double e = c.error();
        std::printf("METRIC %s %.4f ratio\n", c.metric.c_str(), e);
        std::fflush(stdout);
    }
    return 0;
}
