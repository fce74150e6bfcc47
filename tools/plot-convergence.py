#!/usr/bin/env python3
"""Plots a `pathlab-bench converge` CSV on log-log axes, one line per
strategy: relMSE against samples per pixel (error per sample, whatever the
machine) and against render time (what a user waits for), each with the
ideal slope -1 (error variance falls as 1/N, i.e. as 1/time, for an
unbiased estimator) for comparison.

usage: plot-convergence.py CONVERGE.csv OUT.png [TITLE]
Needs Debian's python3-matplotlib (run it with /usr/bin/python3)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main() -> int:
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    rows = list(csv.DictReader(open(sys.argv[1])))
    curves: dict[str, list[tuple[float, float, float]]] = {}
    for row in rows:
        curves.setdefault(row["strategy"], []).append((float(row["spp"]), float(row["seconds"]), float(row["relmse"])))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), dpi=110)
    for ax, column, label in ((axes[0], 0, "samples per pixel"), (axes[1], 1, "render time (s)")):
        for name, points in curves.items():
            ax.loglog([p[column] for p in points], [p[2] for p in points], marker="o", markersize=3, label=name)
        # The ideal slope -1 through the first strategy's last point.
        last = curves[next(iter(curves))][-1]
        xs = sorted({p[column] for points in curves.values() for p in points})
        ax.loglog(xs, [last[2] * last[column] / x for x in xs], linestyle="--", color="grey", label="slope -1 (ideal)")
        ax.set_xlabel(label)
        ax.set_ylabel("relMSE against the reference")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_title("error against samples")
    axes[1].set_title("error against time")
    axes[1].legend()
    fig.suptitle(sys.argv[3] if len(sys.argv) > 3 else "error against samples and time")
    fig.tight_layout()
    fig.savefig(sys.argv[2])
    print(f"wrote {sys.argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
