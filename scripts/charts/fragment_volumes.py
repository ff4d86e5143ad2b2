#!/usr/bin/env python3
# SPDX-License-Identifier: Zlib
"""Fragment volumes against Mott's distribution (paper section 6, Fig. 8).

usage: fragment_volumes.py FRAGMENTS_CSV FRAGMENT_VOLUMES_CSV OUT_PNG

FRAGMENTS_CSV is the runner's fragments.csv (relative_volume per fragment), FRAGMENT_VOLUMES_CSV
its fragment_volumes.csv (logarithmic bins with the fragments' count and Mott's expected count).
Left: the histogram with Mott's expected counts; right: the survival functions P(V >= v) of the
fragments (steps) and of Mott, P(V) = exp(-(6 V / mean V)^(1/3)), over the relative volume.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__.strip().splitlines()[2])
    volumes = sorted(float(r["relative_volume"]) for r in rows(argv[1]))
    bins = rows(argv[2])
    if not volumes or not bins:
        sys.exit(f"{argv[1]}, {argv[2]}: no fragments")
    lower = [float(b["bin_lower"]) for b in bins]
    upper = [float(b["bin_upper"]) for b in bins]
    count = [int(b["count"]) for b in bins]
    expected = [float(b["mott_expected"]) for b in bins]

    fig, (hist, survival) = plt.subplots(1, 2, figsize=(10, 4), layout="constrained")
    widths = [u - lo for lo, u in zip(lower, upper)]
    hist.bar(lower, count, width=widths, align="edge", color="#9ab", edgecolor="#456", label="fragments")
    centres = [math.sqrt(lo * u) for lo, u in zip(lower, upper)]
    hist.plot(centres, expected, "o-", color="#c33", label="Mott, expected")
    hist.set_xscale("log")
    hist.set_xlabel("relative fragment volume V / V$_0$")
    hist.set_ylabel("fragments per bin")
    hist.legend()

    n = len(volumes)
    mean = sum(volumes) / n
    survival.step(volumes, [(n - i) / n for i in range(n)], where="post", color="#27c", label="fragments")
    grid = [volumes[0] * (volumes[-1] / volumes[0]) ** (k / 200) for k in range(201)] if n > 1 else volumes
    survival.plot(grid, [math.exp(-((6 * v / mean) ** (1 / 3))) for v in grid], color="#c33", label="Mott")
    survival.set_xscale("log")
    survival.set_xlabel("relative fragment volume V / V$_0$")
    survival.set_ylabel("P(volume >= V)")
    survival.set_ylim(0, 1.02)
    survival.legend()
    fig.suptitle(f"{n} fragments against Mott's distribution")
    fig.savefig(argv[3], dpi=100)


if __name__ == "__main__":
    main(sys.argv)
