// SPDX-License-Identifier: Zlib
#pragma once
// Fragment volumes against Mott's distribution (paper §6, Fig. 8; Elek and Jaramaz 2008, Eq. 20):
// the probability that a fragment has a volume of at least V is
//     P(V) = exp(-(zeta V)^(1/3)),  zeta = 6 / mean(V),
// i.e. (zeta V)^(1/3) is exponentially distributed with mean 1, so the mean of V is 6 / zeta.
// Volumes are relative to the original body's volume (dimensionless), as in the paper.
// The chart is scripts/charts/fragment_volumes.py's (matplotlib).
#include <string>
#include <vector>

namespace btfracture {

// P(V) above; 1 for V <= 0. Throws btfracture::Error for a non-positive mean.
double mottSurvival(double volume, double meanVolume);

struct MottBin {
    double lower = 0.0, upper = 0.0;  // relative volume range [lower, upper)
    int count = 0;                    // fragments in it
    double expected = 0.0;            // Mott: n (P(lower) - P(upper))
};

struct MottComparison {
    std::vector<double> volumes;  // the relative volumes, ascending
    double mean = 0.0;            // their mean
    std::vector<MottBin> bins;    // logarithmic, binsPerDecade per decade, covering every volume
    // Kolmogorov-Smirnov distance between the fragments' survival function (the fraction with
    // volume >= V) and Mott's P(V).
    double ksDistance = 0.0;
};

// Throws btfracture::Error when `relativeVolumes` is empty or holds a value that is not positive
// and finite, or binsPerDecade is outside [1, 20].
MottComparison compareWithMott(std::vector<double> relativeVolumes, int binsPerDecade = 4);

// CSV, one row per bin: bin_lower,bin_upper,count,mott_expected,survival_fragments,survival_mott
// (both survival functions at the bin's lower edge). Throws Error naming the path on failure.
void writeMottCsv(const std::string& path, const MottComparison& comparison);

}  // namespace btfracture
