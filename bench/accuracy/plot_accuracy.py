#!/usr/bin/env python3
"""Draws docs/images/accuracy.svg from accuracy_bench's CSV files (Python standard library only).

    plot_accuracy.py CSV_DIR OUT.svg

Three panels: missed sensor events against the node-report interval per sensing method, the
time per update of each method, and the width of the 95% interval of a Monte-Carlo detection
rate against the number of seeds (with the wall time to get it).
"""
import csv
import math
import os
import sys

WIDTH, HEIGHT = 1240, 400
PANEL_W, PANEL_H = 330, 260
TOP, LEFT0, GAP = 70, 70, 400
COLOURS = {"sampling": "#d62728", "sub-steps 1": "#ff7f0e", "sub-steps 4": "#2ca02c",
           "sweep": "#1f77b4"}
DASHES = {"sampling": "", "sub-steps 1": "6,3", "sub-steps 4": "2,3", "sweep": ""}


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


class Axes:
    """A panel with a log x axis and a linear or log y axis."""

    def __init__(self, left, x_range, y_range, y_log):
        self.left, self.x_range, self.y_range, self.y_log = left, x_range, y_range, y_log

    def x(self, v):
        lo, hi = (math.log10(a) for a in self.x_range)
        return self.left + (math.log10(v) - lo) / (hi - lo) * PANEL_W

    def y(self, v):
        lo, hi = self.y_range
        if self.y_log:
            lo, hi, v = math.log10(lo), math.log10(hi), math.log10(max(v, self.y_range[0]))
        return TOP + PANEL_H - (v - lo) / (hi - lo) * PANEL_H


def text(x, y, s, size=12, anchor="middle", extra=""):
    return (f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size}" text-anchor="{anchor}" '
            f'font-family="sans-serif" {extra}>{s}</text>')


def frame(ax, title, x_label, y_label, x_ticks, y_ticks, y_fmt):
    out = [f'<rect x="{ax.left}" y="{TOP}" width="{PANEL_W}" height="{PANEL_H}" '
           'fill="none" stroke="#444"/>',
           text(ax.left + PANEL_W / 2, TOP - 28, title, 14, extra='font-weight="bold"'),
           text(ax.left + PANEL_W / 2, TOP + PANEL_H + 38, x_label),
           text(ax.left - 48, TOP + PANEL_H / 2, y_label, extra=
                f'transform="rotate(-90 {ax.left - 48} {TOP + PANEL_H / 2})"')]
    for t in x_ticks:
        out.append(f'<line x1="{ax.x(t):.1f}" y1="{TOP + PANEL_H}" x2="{ax.x(t):.1f}" '
                   f'y2="{TOP + PANEL_H + 5}" stroke="#444"/>')
        out.append(text(ax.x(t), TOP + PANEL_H + 18, f"{t:g}", 11))
    for t in y_ticks:
        out.append(f'<line x1="{ax.left}" y1="{ax.y(t):.1f}" x2="{ax.left + PANEL_W}" '
                   f'y2="{ax.y(t):.1f}" stroke="#ddd"/>')
        out.append(text(ax.left - 6, ax.y(t) + 4, y_fmt(t), 11, "end"))
    return out


def polyline(ax, points, colour, dash="", width=2):
    pts = " ".join(f"{ax.x(x):.1f},{ax.y(y):.1f}" for x, y in points)
    d = f' stroke-dasharray="{dash}"' if dash else ""
    marks = "".join(f'<circle cx="{ax.x(x):.1f}" cy="{ax.y(y):.1f}" r="3" fill="{colour}"/>'
                    for x, y in points)
    return [f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="{width}"{d}/>',
            marks]


def legend(x, y, methods):
    out = []
    for i, m in enumerate(methods):
        yy = y + 16 * i
        d = f' stroke-dasharray="{DASHES[m]}"' if DASHES[m] else ""
        out.append(f'<line x1="{x}" y1="{yy}" x2="{x + 24}" y2="{yy}" stroke="{COLOURS[m]}" '
                   f'stroke-width="2"{d}/>')
        out.append(text(x + 30, yy + 4, m, 11, "start"))
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = read(os.path.join(sys.argv[1], "accuracy_sensing.csv"))
    mc = read(os.path.join(sys.argv[1], "accuracy_montecarlo.csv"))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    intervals = sorted({float(r["interval_s"]) for r in rows})
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'viewBox="0 0 {WIDTH} {HEIGHT}">', '<rect width="100%" height="100%" fill="white"/>']

    # Panel 1: missed events, percent of the truth.
    ax = Axes(LEFT0, (0.08, 6), (0, 50), False)
    svg += frame(ax, "Missed sensor events (2 m/s)", "node-report interval (s)",
                 "missed, % of true events", intervals, [0, 10, 20, 30, 40, 50], lambda t: f"{t:g}%")
    for m in methods:
        pts = [(float(r["interval_s"]), 100.0 * int(r["missed"]) / int(r["truth"]))
               for r in rows if r["method"] == m]
        svg += polyline(ax, pts, COLOURS[m], DASHES[m])
    svg += legend(LEFT0 + 12, TOP + 16, methods)

    # Panel 2: time per update.
    times = [float(r["us_per_update"]) for r in rows]
    lo = 10 ** math.floor(math.log10(min(times)))
    hi = 10 ** math.ceil(math.log10(max(times)))
    ax = Axes(LEFT0 + GAP, (0.08, 6), (lo, hi), True)
    ticks = [lo * 10 ** k for k in range(int(round(math.log10(hi / lo))) + 1)]
    svg += frame(ax, "Engine time per update", "node-report interval (s)", "microseconds",
                 intervals, ticks, lambda t: f"{t:g}")
    for m in methods:
        pts = [(float(r["interval_s"]), float(r["us_per_update"])) for r in rows if r["method"] == m]
        svg += polyline(ax, pts, COLOURS[m], DASHES[m])
    svg += legend(LEFT0 + GAP + PANEL_W - 110, TOP + 16, methods)

    # Panel 3: confidence interval width against seeds, wall time annotated.
    seeds = [int(r["seeds"]) for r in mc]
    widths = [100 * float(r["ci_width"]) for r in mc]
    ax = Axes(LEFT0 + 2 * GAP, (seeds[0] * 0.8, seeds[-1] * 1.6), (0.1, 10), True)
    svg += frame(ax, "Monte Carlo: 95% interval of a rate", "seeds (hazard_replay runs)",
                 "interval width, percentage points", seeds[::2], [0.1, 1, 10], lambda t: f"{t:g}")
    svg += polyline(ax, list(zip(seeds, widths)), "#1f77b4")
    for r, w in zip(mc[1::2], widths[1::2]):
        svg.append(text(ax.x(int(r["seeds"])), ax.y(w) - 10, f'{float(r["wall_s"]):.2g} s', 10))
    svg.append(text(ax.left + PANEL_W - 6, TOP + 18, "labels: wall time so far", 10, "end"))
    svg.append("</svg>")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
