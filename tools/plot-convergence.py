#!/usr/bin/env python3
"""Plots a `pathlab-bench converge` CSV: relMSE against render time on
log-log axes, one line per strategy, with the ideal slope -1 (error variance
falls as 1/N, i.e. as 1/time, for an unbiased estimator) for comparison.

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
    curves: dict[str, list[tuple[float, float]]] = {}
    for row in rows:
        curves.setdefault(row["strategy"], []).append((float(row["seconds"]), float(row["relmse"])))
    fig, ax = plt.subplots(figsize=(7, 5), dpi=110)
    for name, points in curves.items():
        ax.loglog([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3, label=name)
    # The ideal 1/time slope through the first strategy's last point.
    t, e = curves[next(iter(curves))][-1]
    times = sorted({p[0] for points in curves.values() for p in points})
    ax.loglog(times, [e * t / x for x in times], linestyle="--", color="grey", label="slope -1 (ideal)")
    ax.set_xlabel("render time (s)")
    ax.set_ylabel("relMSE against the reference")
    ax.set_title(sys.argv[3] if len(sys.argv) > 3 else "error against time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2])
    print(f"wrote {sys.argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
