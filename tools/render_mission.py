#!/usr/bin/env python3
"""Render a finished hazard-search run as a picture (SVG, and PNG through rsvg-convert).

Usage:
  render_mission.py --alog RUN.alog --hazards hazards.txt [--summary summary.json]
                    [--svg OUT.svg] [--png OUT.png] [--title TEXT] [--detail auto|objects|field]
                    [--benign-shape square] [--benign-color light_blue] ...

What is drawn (legend in docs/mission-logic.md, "The picture"):
  - the search region (hazard file `region =`, else the grader's VIEW_POLYGON `search_region`,
    else UHZ_MISSION_PARAMS `search_region=`);
  - every object of the hazard file in the original's marker styles: VIEW_MARKER postings in the
    log win (they carry the mission's shape, colour, width and benign transparency); otherwise
    hazards are green triangles and benign objects light_blue triangles (differences.md D17/D18,
    manual 7.6), overridable with --benign-shape/--benign-color; benign fill transparency
    1 - hr (0.5 without hr, docs/messages.md);
  - each vehicle's track from NODE_REPORT X/Y (one colour per vehicle) and its swath coverage:
    the sensor's VIEW_POLYGON `sensor_swath_<v>` rectangles while the sensor was on (white
    fill), or, without them, the track widened to the acked swath width where the 2 s turn
    rate allowed sensing;
  - detections and classifications from VIEW_CIRCLE as posted (D19: white 12-vertex circles, pink
    when aspect degradation changed the outcome; pentagons yellow for "hazard", green for "benign",
    pink fill when aspect changed the answer); without VIEW_CIRCLE postings, from
    UHZ_DETECTION_REPORT / UHZ_HAZARD_REPORT with the D19 colours; in the field view, one dot
    per cued position in the colour of its latest cue;
  - the last HAZARDSET_REPORT: dashed rings around the reported objects (objects view only), red
    rings around the hazards it missed;
  - the score table from HAZARDSET_EVAL in the log (latest per vehicle), else from summary.json;
  - a scale bar and a north arrow.

Contract (what the picture guarantees, whatever the inputs):
  - Everything stays inside the 1200 x 900 frame: the map is clipped to its viewport, every panel
    text is fitted to the panel's width (smaller font, then an ellipsis), and the panel takes the
    most detailed of its layouts that fits its height (see `panel_layouts`).
  - Two levels of detail, chosen from the number of objects (`DETAIL_MAX_OBJECTS`, or --detail):
    "objects" draws each object with its label, the viewer's cues and the report rings as posted;
    "field" draws no labels, markers sized to the mean object spacing and written as one SVG path
    per style, one dot per cued object (its latest cue), and rings only around missed hazards.
  - Speed: the .alog is read once, line by line; each line is split once into time, variable and
    the rest, and only the variables drawn are parsed (reports that are only a fallback are kept
    raw and parsed only when needed). Tracks and swath strips are reduced to the points that move
    the picture by a pixel before they are written.
  - Input problems never stop the picture: malformed lines and values are reported on stderr with
    their line number and skipped.
  Rejected: one SVG element per object, cue and swath rectangle (11 MB and 12 s for 10,000
  objects); a raster density of the cues (needs an image encoder, and hides which object is which).

Python 3 standard library only. The drawing is in tools/mission_picture/ (one module per part of
the picture), the reading of the inputs in tools/mission_files/.
"""

import argparse
import sys

from mission_picture.layout import DETAIL_MAX_OBJECTS
from mission_picture.output import write_png, write_svg
from mission_picture.picture import render
from mission_picture.run_log import Run, read_hazards, read_log, read_scores


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--alog", help="the run's .alog")
    parser.add_argument("--hazards", help="the hazard file (ground truth)")
    parser.add_argument("--summary", help="optional summary.json with the scores")
    parser.add_argument("--svg", default="mission.svg", help="SVG output (default mission.svg)")
    parser.add_argument("--png", help="PNG output (needs rsvg-convert); default: the SVG name .png")
    parser.add_argument("--no-png", action="store_true", help="write the SVG only")
    parser.add_argument("--title", help="title above the map")
    parser.add_argument("--detail", choices=("auto", "objects", "field"), default="auto",
                        help="objects: labels and the viewer's cues per object; field: markers "
                             "and dots for large fields; auto (default): field beyond %d objects"
                             % DETAIL_MAX_OBJECTS)
    parser.add_argument("--hazard-shape", default="triangle", help="default hazard marker shape")
    parser.add_argument("--hazard-color", default="green", help="default hazard colour (D17)")
    parser.add_argument("--benign-shape", default="triangle",
                        help="default benign marker shape (Jake: square)")
    parser.add_argument("--benign-color", default="light_blue", help="default benign colour (D18)")
    opts = parser.parse_args(argv)

    run = Run()
    if opts.alog:
        read_log(opts.alog, run)
    objects, region = read_hazards(opts.hazards) if opts.hazards else ([], None)
    summary = read_scores(opts.summary, run) if opts.summary else None
    if summary and not opts.title and isinstance(summary.get("title"), str):
        opts.title = summary["title"]

    svg = render(run, objects, region, opts)
    if not write_svg(svg, opts.svg):
        return 1
    if opts.no_png:
        return 0
    return 0 if write_png(svg, opts.svg, opts.png) else 1


if __name__ == "__main__":
    sys.exit(main())
