#!/usr/bin/env python3
"""Frame time of pWebViewer's page while panning a field of many objects in headless chromium.

Generates a replay JSON (markers, detection circles, swath-like polygons, seglists and a few
vehicles with trails), serves it with the page's files, opens the page with ?flush=1 (so each
frame's time includes rasterisation), drags the map with the mouse for --frames frames, and
prints the median and p99 of the draw time per frame and of the interval between drawn frames,
and the browser's CPU time per frame (all its processes: a figure other jobs on the machine do
not inflate, unlike the wall-clock times).

  build/pyenv/bin/python bench/viewer/frame_time.py [--objects=100000] [--frames=200]
"""

import argparse
import os
import random
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests/apps/pWebViewer/browser"))
from browser_support import browser_page, static_site, mail, replay_doc, next_frame  # noqa: E402

SHAPES = ["triangle", "square", "circle", "diamond"]
COLORS = ["red", "light_blue", "yellow", "green", "orange", "white"]


def field(objects, side_m, seed):
    """`objects` VIEW_* postings spread over a square of side_m metres, plus 10 vehicles."""
    rng = random.Random(seed)
    mails = []
    t = 1000.0
    n_markers = objects * 8 // 10
    n_circles = objects // 10
    n_polygons = objects // 20
    n_seglists = objects - n_markers - n_circles - n_polygons
    xy = lambda: (rng.uniform(0, side_m), rng.uniform(0, side_m))  # noqa: E731
    for i in range(n_markers):
        x, y = xy()
        mails.append(mail("VIEW_MARKER", f"x={x:.2f},y={y:.2f},width=8,primary_color="
                          f"{rng.choice(COLORS)},type={rng.choice(SHAPES)},label={i}", t))
    for i in range(n_circles):
        x, y = xy()
        mails.append(mail("VIEW_CIRCLE", f"x={x:.2f},y={y:.2f},radius=10,vertices=12,"
                          f"edge_color=white,fill_color=white,vertex_size=0,edge_size=1,"
                          f"fill_transparency=0.3,label=c{i}", t))
    for i in range(n_polygons):
        x, y = xy()
        mails.append(mail("VIEW_POLYGON", f"pts={{{x:.1f},{y:.1f}:{x + 25:.1f},{y:.1f}:"
                          f"{x + 25:.1f},{y + 5:.1f}:{x:.1f},{y + 5:.1f}}},label=p{i},"
                          "edge_color=green,fill_color=white,edge_size=1,fill_transparency=0.2", t))
    for i in range(n_seglists):
        x, y = xy()
        mails.append(mail("VIEW_SEGLIST", f"pts={{{x:.1f},{y:.1f}:{x + 15:.1f},{y + 15:.1f}}},"
                          f"edge_color=gray70,vertex_size=0,edge_size=1,label=s{i}", t))
    for v in range(10):
        x, y = xy()
        for k in range(200):
            mails.append(mail("NODE_REPORT", f"NAME=v{v},X={x + k:.1f},Y={y:.1f},HDG=90,"
                              "TYPE=kayak,LENGTH=4", t + k * 0.25))
    return mails


def browser_cpu_s(profile_dir):
    """User + system CPU seconds of every process of the browser (found by its profile folder):
    the work per frame even when other jobs share the cores and stretch the wall-clock times."""
    total = 0
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                if profile_dir.encode() not in f.read():
                    continue
            with open("/proc/%s/stat" % pid) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])  # utime, stime (clock ticks)
        except OSError:
            continue
    return total / os.sysconf("SC_CLK_TCK")


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def pan(page, frames, step_px):
    """Drags the map step_px per frame, waiting for a drawn frame after each move."""
    x, y = 400, 400
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(frames):
        x += step_px if (i // 50) % 2 == 0 else -step_px  # back and forth over the field
        page.mouse.move(x, y)
        next_frame(page)
    page.mouse.up()
    stats = page.evaluate("window.viewerFrameStats()")
    return stats


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objects", type=int, default=100000)
    ap.add_argument("--frames", type=int, default=200)
    ap.add_argument("--side", type=float, default=5000.0, help="field side, metres")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    doc = replay_doc(field(args.objects, args.side, args.seed))
    with static_site(doc) as url, browser_page(1280, 800) as page:
        page.goto(url + "?replay=replay.json&flush=1")
        page.wait_for_function("window.viewerState && window.viewerState().replay !== undefined",
                               timeout=120000)
        page.evaluate("window.viewerSeek(1e12)")
        counts = page.evaluate("(() => { const s = window.viewerState(); return [s.markers.length,"
                               " s.circles.length, s.polygons.length, s.seglists.length,"
                               " Object.keys(s.vehicles).length]; })()")
        print(f"objects: markers={counts[0]} circles={counts[1]} polygons={counts[2]} "
              f"seglists={counts[3]} vehicles={counts[4]}")
        for name, fraction in [("whole field in view", 1.0), ("a tenth of the field wide", 0.1)]:
            page.evaluate(f"""(() => {{ const v = window.viewerView();
                window.viewerView({{cx: {args.side / 2}, cy: {args.side / 2},
                                   scale: v.w / ({args.side * fraction} * 1.05)}}); }})()""")
            next_frame(page)
            cpu0 = browser_cpu_s(page.profile_dir)
            stats = pan(page, args.frames, 4)
            cpu_ms = 1000 * (browser_cpu_s(page.profile_dir) - cpu0) / args.frames
            draw = stats["draw_ms"][-args.frames:]
            interval = stats["interval_ms"][-args.frames:]
            print(f"{name}: {len(draw)} frames, objects drawn in the last {stats['objects_drawn']}; "
                  f"draw+raster ms median {statistics.median(draw):.1f} p99 {percentile(draw, 0.99):.1f}; "
                  f"frame interval ms median {statistics.median(interval):.1f} "
                  f"p99 {percentile(interval, 0.99):.1f}; browser CPU per frame {cpu_ms:.1f} ms")
        if page.errors:
            print("page errors:", page.errors)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
