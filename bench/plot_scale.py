#!/usr/bin/env python3
"""Plots bench_scale's CSV: the time of one step against the number of triangles (log-log), ours
(isotropic and anisotropic Loop steps) beside one smooth_shape step, and the peak memory.

usage: python3 bench/plot_scale.py bench_scale.csv [OUTPUT.png]   (needs python3-matplotlib)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {"smooth_shape": "CGAL smooth_shape, one step",
          "isotropic": "ours, one isotropic Loop step (whole call)",
          "anisotropic": "ours, one anisotropic step with prefilter (whole call)"}


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["quantity"] == "seconds" and r["kind"] in LABELS]
    out = sys.argv[2] if len(sys.argv) > 2 else "bench_scale.png"
    fig, (ax_t, ax_m) = plt.subplots(1, 2, figsize=(11, 4.2))
    for kind, label in LABELS.items():
        pts = sorted((int(r["triangles"]), float(r["median_seconds"]), float(r["peak_mb"])) for r in rows if r["kind"] == kind)
        if not pts:
            continue
        tri = [p[0] / 1e6 for p in pts]
        ax_t.plot(tri, [p[1] for p in pts], "o-", label=label)
        ax_m.plot(tri, [p[2] / 1024 for p in pts], "o-", label=label)
    for ax, what in ((ax_t, "seconds (median)"), (ax_m, "peak memory, GB")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("million triangles")
        ax.set_ylabel(what)
        ax.grid(True, which="both", alpha=0.3)
    ax_t.legend(fontsize=8)
    ax_t.set_title("time of one step")
    ax_m.set_title("peak resident memory of the process")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
