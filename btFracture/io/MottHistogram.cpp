// SPDX-License-Identifier: Zlib
#include <btFracture/io/MottHistogram.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/PortableMath.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace btfracture {

double mottSurvival(double volume, double meanVolume) {
    if (!(meanVolume > 0.0) || !std::isfinite(meanVolume))
        throw Error("mottSurvival: the mean fragment volume must be positive and finite, got " +
                    std::to_string(meanVolume));
    if (volume <= 0.0) return 1.0;
    const double zeta = 6.0 / meanVolume;
    return pmath::exp(-std::cbrt(zeta * volume));
}

MottComparison compareWithMott(std::vector<double> volumes, int binsPerDecade) {
    if (volumes.empty()) throw Error("compareWithMott: no fragment volumes");
    if (binsPerDecade < 1 || binsPerDecade > 20)
        throw Error("compareWithMott: bins per decade must lie in [1, 20], got " +
                    std::to_string(binsPerDecade));
    for (double v : volumes)
        if (!(v > 0.0) || !std::isfinite(v))
            throw Error("compareWithMott: fragment volumes must be positive and finite, got " +
                        std::to_string(v));
    std::sort(volumes.begin(), volumes.end());
    MottComparison c;
    double sum = 0.0;
    for (double v : volumes) sum += v;
    c.mean = sum / static_cast<double>(volumes.size());
    const double n = static_cast<double>(volumes.size());
    for (size_t i = 0; i < volumes.size(); ++i) {
        // The fragments' survival steps from (n - i) / n down to (n - i - 1) / n at volumes[i].
        const double p = mottSurvival(volumes[i], c.mean);
        c.ksDistance = std::max({c.ksDistance, std::abs((n - i) / n - p), std::abs((n - i - 1) / n - p)});
    }
    const int first = static_cast<int>(std::floor(pmath::log10(volumes.front()) * binsPerDecade));
    const int last = static_cast<int>(std::floor(pmath::log10(volumes.back()) * binsPerDecade));
    size_t next = 0;
    for (int k = first; k <= last; ++k) {
        MottBin bin;
        bin.lower = pmath::pow(10.0, static_cast<double>(k) / binsPerDecade);
        bin.upper = pmath::pow(10.0, static_cast<double>(k + 1) / binsPerDecade);
        // Bin edges from pow() may round differently from log10(): the last bin takes the rest.
        while (next < volumes.size() && (volumes[next] < bin.upper || k == last)) {
            ++bin.count;
            ++next;
        }
        bin.expected = n * (mottSurvival(bin.lower, c.mean) - mottSurvival(bin.upper, c.mean));
        c.bins.push_back(bin);
    }
    c.volumes = std::move(volumes);
    return c;
}

void writeMottCsv(const std::string& path, const MottComparison& c) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot create histogram file '" + path + "'");
    out << "bin_lower,bin_upper,count,mott_expected,survival_fragments,survival_mott\n";
    const double n = static_cast<double>(c.volumes.size());
    for (const MottBin& b : c.bins) {
        const double atLeast = static_cast<double>(
            c.volumes.end() - std::lower_bound(c.volumes.begin(), c.volumes.end(), b.lower));
        char line[256];
        std::snprintf(line, sizeof line, "%.9g,%.9g,%d,%.9g,%.9g,%.9g\n", b.lower, b.upper, b.count,
                      b.expected, atLeast / n, mottSurvival(b.lower, c.mean));
        out << line;
    }
    out.close();
    if (out.fail()) throw Error("writing histogram file '" + path + "' failed");
}

}  // namespace btfracture
