#!/usr/bin/env python3
"""Plots `poresph bench --accuracy --json` output: error against wall time, one marker per run.

    python3 bench/plot_accuracy.py accuracy.json accuracy.png

Needs matplotlib (Debian's python3-matplotlib, installed with ParaView by scripts/install-deps.sh).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")  # headless
import matplotlib.pyplot as plt  # noqa: E402


def main(src, dst):
    with open(src) as f:
        recs = json.load(f)
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
    markers = {"cubic_spline": "o", "wendland_c2": "s", "quintic_spline": "^"}
    for case in sorted({r["case"] for r in recs}):
        for kernel, marker in markers.items():
            rs = sorted((r for r in recs if r["case"] == case and r["kernel"] == kernel), key=lambda r: r["seconds"])
            if not rs:
                continue
            ax.loglog([r["seconds"] for r in rs], [100 * r["error"] for r in rs], marker=marker, label=f"{case}, {kernel}")
            for r in rs:
                ax.annotate(f"R/{r['support_per_spacing']:g}", (r["seconds"], 100 * r["error"]), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("error (%)")
    ax.set_title("poresph: run time against error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(dst)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_accuracy.py ACCURACY.json OUT.png")
    main(sys.argv[1], sys.argv[2])
