#!/usr/bin/env python3
"""Draws a pathlab-demo figure (JSON written by lab/figure.cpp) with
matplotlib: plots side by side, each with lines, histograms, scatter
points, bars or an image. usage: plot-demo.py FIGURE.json
Needs Debian's python3-matplotlib (run it with /usr/bin/python3)."""
import json
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
except ImportError:
    print("plot-demo.py: matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
    sys.exit(3)


def draw(ax, plot):
    labelled = False
    categories = plot["categories"]
    bar_series = [s for s in plot["series"] if s["kind"] == "bars"]
    width = 0.8 / max(1, len(bar_series))
    bar_index = 0
    for s in plot["series"]:
        kind, label = s["kind"], s["label"] or None
        labelled |= label is not None
        style = "--" if s["dashed"] else "-"
        if kind == "line":
            ax.plot(s["x"], s["y"], style, label=label, linewidth=1.6)
        elif kind == "scatter":
            ax.scatter(s["x"], s["y"], s=4, alpha=0.6, label=label, linewidths=0)
        elif kind == "hist":
            edges, heights = s["x"], s["y"]
            ax.stairs(heights, edges, fill=True, alpha=0.45, label=label)
        elif kind == "bars":
            positions = [i + (bar_index - (len(bar_series) - 1) / 2) * width for i in range(len(s["y"]))]
            ax.bar(positions, s["y"], width=width, label=label)
            bar_index += 1
        elif kind == "image":
            ax.imshow(mpimg.imread(s["path"]), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
    if categories:
        ax.set_xticks(range(len(categories)))
        ax.set_xticklabels(categories)
    if plot["xlog"]:
        ax.set_xscale("log")
    if plot["ylog"]:
        ax.set_yscale("log")
    if plot["equal"]:
        ax.set_aspect("equal")
    ax.set_title(plot["title"], fontsize=10)
    ax.set_xlabel(plot["xlabel"])
    ax.set_ylabel(plot["ylabel"])
    if not any(s["kind"] == "image" for s in plot["series"]):
        ax.grid(True, which="both", alpha=0.25)
    if labelled:
        ax.legend(fontsize=8)


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    figure = json.load(open(sys.argv[1]))
    plots = figure["plots"]
    fig, axes = plt.subplots(1, len(plots), figsize=(4.6 * len(plots), 4.2), dpi=100, squeeze=False)
    for ax, plot in zip(axes[0], plots):
        draw(ax, plot)
    fig.suptitle(figure["title"])
    fig.tight_layout()
    fig.savefig(figure["out"])
    return 0


if __name__ == "__main__":
    sys.exit(main())
