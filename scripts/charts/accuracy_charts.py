#!/usr/bin/env python3
# SPDX-License-Identifier: Zlib
"""Charts of the accuracy-vs-time study (make bench-accuracy) from its runs.csv and steps.csv.

usage: accuracy_charts.py DIR

Writes into DIR: pareto_<case>.png (error against time in fracture, one point per method: SIF
error for the solver-level cases, mean fracture-surface distance to FULL for the scenes),
step_time_vs_elements.png and step_time_vs_front_length.png (time per propagation step of the
FULL and EST growth runs, paper section 4.4), memory_vs_elements.png (peak memory against the
largest BEM mesh, per method family).
"""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def is_scene(run):
    return int(run["fragments"]) >= 0


def pareto_error(run):
    """[%], or None when the run has no reference."""
    value = float(run["surface_mean_rel"] if is_scene(run) else run["sif_error"])
    return None if value < 0 else 100 * value


def pareto_time(run):
    return float(run["engine_total_s"] if is_scene(run) else run["fracture_s"])


def save(fig, directory, name, written):
    fig.savefig(os.path.join(directory, name), dpi=100)
    plt.close(fig)
    written.append(name)


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    directory = argv[1]
    runs = rows(os.path.join(directory, "runs.csv"))
    steps = rows(os.path.join(directory, "steps.csv"))
    written = []

    cases = list(OrderedDict.fromkeys(r["case"] for r in runs))
    for case in cases:
        fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
        scene = False
        for run in (r for r in runs if r["case"] == case):
            scene = is_scene(run)
            error = pareto_error(run)
            if error is not None:
                ax.plot([pareto_time(run)], [error], "o", markersize=8, label=run["method"])
        ax.set_xscale("log")
        ax.set_xlabel("time in fracture [s]")
        ax.set_ylabel("fracture surface distance to FULL [% of size]" if scene else "SIF error [%]")
        ax.set_title(case)
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend()
        save(fig, directory, f"pareto_{case}.png", written)

    # Step time against elements and against active front length (FULL and EST growth runs).
    by_run = OrderedDict()
    for s in steps:
        by_run.setdefault((s["case"], s["method"]), []).append(s)
    elements, front = plt.subplots(figsize=(8, 5.2), layout="constrained"), plt.subplots(
        figsize=(8, 5.2), layout="constrained")
    for (case, method), samples in by_run.items():
        if len(samples) < 3 or method not in ("FULL", "EST"):
            continue
        # The closing step in which every node arrested does no work.
        work = [s for s in samples if float(s["step_s"]) >= 1e-3]
        elements[1].plot([int(s["elements"]) for s in work], [float(s["step_s"]) for s in work],
                         label=f"{case} {method}")
        if method == "EST":
            est = [s for s in work if s["estimated"] == "1"]
            front[1].plot([float(s["active_front_m"]) for s in est], [float(s["step_s"]) for s in est],
                          label=f"{case} {method}")
    elements[1].set(xscale="log", yscale="log", xlabel="BEM elements (surface + crack triangles)",
                    ylabel="step time [s]", title="time per propagation step vs BEM elements")
    front[1].set(xlabel="active front length [m]", ylabel="step time [s]",
                 title="EST: time per propagation step vs active front length")
    for fig, ax in (elements, front):
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=2)
    save(elements[0], directory, "step_time_vs_elements.png", written)
    save(front[0], directory, "step_time_vs_front_length.png", written)

    # Peak memory against the largest BEM mesh of the run, per method family.
    fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
    families = OrderedDict()
    for run in (r for r in runs if not r["note"].startswith("run failed")):
        family = "HYBRID" if run["method"].startswith("HYB") else run["method"]
        families.setdefault(family, []).append(
            (int(run["bem_triangles"]) + int(run["crack_triangles"]), float(run["peak_rss_mb"])))
    for family, points in sorted(families.items()):
        ax.plot([p[0] for p in points], [p[1] for p in points], "o", label=family)
    ax.set(xscale="log", yscale="log", xlabel="surface + crack triangles at the end",
           ylabel="peak resident memory [MB]", title="peak memory vs BEM elements")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    save(fig, directory, "memory_vs_elements.png", written)
    print("accuracy_charts.py: wrote " + ", ".join(written))


if __name__ == "__main__":
    main(sys.argv)
