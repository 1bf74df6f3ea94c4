#!/usr/bin/env python3
"""Draws docs/images/performance.svg from process_bench --csv lines (Python standard library only).

    plot_performance.py SWEEP.csv OUT.svg

Two panels, field size on the x axis, one line per fleet size: the sensor's CPU seconds per
simulated hour, and its resident memory. When the CSV holds "original" rows (process_bench
--original=PATH), the original's CPU at its nominal tick (the measured CPU scaled by nominal /
achieved iterations, the CSV's last column) is drawn as dashed lines; without them, the
original's figures quoted in docs/performance.md (warp 10, reference MOOSDB, another machine)
are drawn as hollow marks, labelled as quoted. The SVG helpers are those of
bench/accuracy/plot_accuracy.py.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "accuracy"))
from plot_accuracy import LEFT0, TOP, Axes, frame, polyline, text  # noqa: E402  (shared helpers)

WIDTH, HEIGHT, GAP = 840, 400, 420
FLEET_COLOURS = {1: "#2ca02c", 10: "#1f77b4", 100: "#d62728"}
# The original's quoted figures (docs/performance.md): (objects, vehicles, CPU s per simulated hour,
# low and high).
QUOTED_ORIGINAL = [(10000, 1, 82, 82), (10000, 10, 735, 735), (100000, 10, 9900, 14700)]


def log_ticks(lo, hi):
    first, last = int(math.floor(math.log10(lo))), int(math.ceil(math.log10(hi)))
    return [10 ** k for k in range(first, last + 1)]


def series(rows, program, value):
    """{vehicles: [(objects, value), ...]} of the completed runs of one program (a value of None,
    or one that is not a positive finite number, leaves the run out)."""
    out = {}
    for r in rows:
        if r["program"] != program or r["ok"] != "1":
            continue
        y = value(r)
        if y is not None and math.isfinite(y) and y > 0:
            out.setdefault(int(r["vehicles"]), []).append((int(r["objects"]), y))
    return {v: sorted(p) for v, p in sorted(out.items())}


def at_nominal_tick(row):
    """The CPU per simulated hour at the nominal tick ("nan" when unknown, which series() leaves
    out); older CSVs have only the measured one."""
    return float(row.get("sensor_cpu_s_per_h_nominal_tick") or row["sensor_cpu_s_per_h"])


def legend(x, y, fleets, with_quoted, with_measured_original=False):
    out = []
    for i, v in enumerate(fleets):
        yy = y + 16 * i
        colour = FLEET_COLOURS.get(v, "#444")
        out.append(f'<line x1="{x}" y1="{yy}" x2="{x + 24}" y2="{yy}" stroke="{colour}" '
                   'stroke-width="2"/>')
        out.append(text(x + 30, yy + 4, f"ours, {v} vehicle{'s' if v > 1 else ''}", 11, "start"))
    if with_quoted:
        yy = y + 16 * len(fleets)
        out.append(f'<circle cx="{x + 12}" cy="{yy}" r="4" fill="none" stroke="#444"/>')
        out.append(text(x + 30, yy + 4, "original, as quoted", 11, "start"))
    if with_measured_original:
        yy = y + 16 * len(fleets)
        out.append(f'<line x1="{x}" y1="{yy}" x2="{x + 24}" y2="{yy}" stroke="#444" '
                   'stroke-width="2" stroke-dasharray="6,3"/>')
        out.append(text(x + 30, yy + 4, "original at its nominal tick (measured)", 11, "start"))
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    cpu = series(rows, "ours", lambda r: float(r["sensor_cpu_s_per_h"]))
    rss = series(rows, "ours", lambda r: int(r["sensor_rss_kb"]) / 1024.0)
    theirs = series(rows, "original", at_nominal_tick)
    quoted = [] if theirs else QUOTED_ORIGINAL
    if not cpu:
        sys.exit("plot_performance.py: no completed runs of ours in " + sys.argv[1])
    objects = sorted({o for pts in cpu.values() for o, _ in pts})
    x_range = (objects[0] / 2, objects[-1] * 2)
    warp = rows[0]["warp"]
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'viewBox="0 0 {WIDTH} {HEIGHT}">', '<rect width="100%" height="100%" fill="white"/>']

    values = [y for pts in list(cpu.values()) + list(theirs.values()) for _, y in pts]
    values += [q[3] for q in quoted]
    # A decade of headroom above the highest point, where the legend goes.
    y_range = (10 ** math.floor(math.log10(min(values))),
               10 ** (math.ceil(math.log10(max(values))) + 1))
    ax = Axes(LEFT0, x_range, y_range, True)
    svg += frame(ax, f"Sensor CPU per simulated hour (warp {warp})", "objects in the field",
                 "CPU seconds", objects, log_ticks(*y_range), lambda t: f"{t:g}")
    for v, pts in cpu.items():
        svg += polyline(ax, pts, FLEET_COLOURS.get(v, "#444"))
    for v, pts in theirs.items():
        svg += polyline(ax, pts, FLEET_COLOURS.get(v, "#444"), "6,3")
    for o, v, lo, hi in quoted:
        colour = FLEET_COLOURS.get(v, "#444")
        svg.append(f'<line x1="{ax.x(o):.1f}" y1="{ax.y(lo):.1f}" x2="{ax.x(o):.1f}" '
                   f'y2="{ax.y(hi):.1f}" stroke="{colour}"/>')
        for y in {lo, hi}:
            svg.append(f'<circle cx="{ax.x(o):.1f}" cy="{ax.y(y):.1f}" r="4" fill="none" '
                       f'stroke="{colour}"/>')
    svg += legend(LEFT0 + 12, TOP + 16, list(cpu), bool(quoted), bool(theirs))

    values = [y for pts in rss.values() for _, y in pts]
    y_range = (10 ** math.floor(math.log10(min(values))), 10 ** math.ceil(math.log10(max(values))))
    ax = Axes(LEFT0 + GAP, x_range, y_range, True)
    svg += frame(ax, "Sensor resident memory (markers off)", "objects in the field", "MB",
                 objects, log_ticks(*y_range), lambda t: f"{t:g}")
    for v, pts in rss.items():
        svg += polyline(ax, pts, FLEET_COLOURS.get(v, "#444"))
    svg += legend(LEFT0 + GAP + 12, TOP + 16, list(rss), False)
    svg.append("</svg>")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
