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
    hazards are green triangles and benign objects light_blue triangles (rulings D17/D18,
    manual 7.6), overridable with --benign-shape/--benign-color; benign fill transparency
    1 - hr (0.5 without hr, spec 5.4);
  - each vehicle's track from NODE_REPORT X/Y (one colour per vehicle) and its swath coverage:
    the sensor's VIEW_POLYGON `sensor_swath_<v>` rectangles while the sensor was on (white
    fill), or, without them, the track widened to the acked swath width where the spec-8.2 turn
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

Python 3 standard library only.
"""

import argparse
import colorsys
import json
import math
import os
import re
import shutil
import subprocess
import sys
from functools import lru_cache
from xml.sax.saxutils import escape

# ---------------------------------------------------------------------------------------------
# Layout and style constants (pixels unless stated).

CANVAS_W, CANVAS_H = 1200, 900
MAP_X, MAP_Y, MAP_W, MAP_H = 20, 60, 820, 820      # the map viewport
PANEL_X = MAP_X + MAP_W + 20                        # the right-hand panel (scores, legend)
PANEL_RIGHT = CANVAS_W - 10                         # no panel text or box goes past this
PANEL_BOTTOM = CANVAS_H - 10                        # nor below this
PANEL_W = PANEL_RIGHT - PANEL_X
TITLE_FONT_PX, TITLE_MIN_FONT_PX = 24, 14
MAP_BACKGROUND = "#1b2736"                          # dark, like a viewer: white cues stay visible
VEHICLE_COLOURS = ["#ff8c42", "#e040fb", "#26c6da", "#c0ca33", "#ff5252", "#ffffff"]
GOLDEN_ANGLE_DEG = 137.508                          # hue step of the colours past the palette
SWATH_OPACITY = 0.18
LIGHT_LUMINANCE = 0.8                               # relative luminance above which a name on
                                                    # the light panel gets a dark outline
DETECTION_RADIUS_M = 10.0                           # D19 / spec 5.3
DEFAULT_MARKER_WIDTH_M = 8.0                        # manual 7.6
MIN_MARKER_PX = 7.0                                 # objects mode: a marker is never smaller
REPORT_RING_M = 15.0                                # drawn outside the radius-10 cues
SENSOR_MAX_TURN_RATE_DPS = 1.5                      # manual 8
SENSOR_MAX_SPEED_MPS = 2.0                          # rulings D14
TURN_WINDOW_S = 2.0                                 # spec 8.2
TRACK_STEP_PX = 1.0                                 # track points closer than this are dropped
SIMPLIFY_TOLERANCE_PX = 0.4                         # Douglas-Peucker: invisible at 1200 x 900
# Consecutive swath rectangles join into one strip while their centres are at most one swath
# length apart (they touch or overlap) plus this slack for heading noise; beyond it the strip
# breaks, because the sensor left a hole there.
SWATH_JOIN_SLACK_M = 1.0
SWATH_WIDTH_CHANGE = 0.01                           # relative width change that starts a new strip

# Level of detail. At 300 objects on the 820 px map the mean spacing is about 47 px: closer
# than that, labels (about 25 px wide) and the radius-10 m cues of neighbours start to overlap
# in the fields we generate, so beyond it the picture switches to the "field" style.
DETAIL_MAX_OBJECTS = 300
FIELD_MARKER_SPACING_FRACTION = 0.55                # marker width / mean object spacing
FIELD_MARKER_MIN_PX, FIELD_MARKER_MAX_PX = 3.0, 9.0
FIELD_HAZARD_SCALE = 1.35                           # hazards larger: they are what is searched for
FIELD_TRACK_WIDTH_PX = 1.2
OBJECTS_TRACK_WIDTH_PX = 2.0
FIELD_SWATH_OPACITY = 0.28                          # coverage reads as a layer under the dots
FIELD_CUE_DOT_FRACTION = 0.65                       # cue dot diameter / benign marker width
FIELD_MISSED_RING_FRACTION = 1.0                    # missed-hazard ring radius / hazard marker
FIELD_LEGEND_SYMBOL_SCALE = 2.0                     # legend symbols larger than on the map,
LEGEND_SYMBOL_MAX_PX = 16.0                         # but no larger than this (rows are 17-24)
FIELD_LEGEND_DOT_SCALE, LEGEND_DOT_MAX_PX = 2.5, 10.0   # the same for the cue dots
OPACITY_STEP = 0.1                                  # field style: benign fill alphas are binned

# Text widths: the advance widths of DejaVu Sans and DejaVu Sans Bold (the SVG's first font;
# Debian fonts-dejavu-core 2.37, hmtx table) for the characters 32 (space) to 126 (~), in
# hundredths of an em, rounded up. Any other character counts as one em (bold 1.12), at least
# its width in these fonts. An estimate is therefore never short (the tests read the installed
# fonts to check it), and a fitted text stays inside the panel.
DEJAVU_SANS_CEM = (
    32, 41, 46, 84, 64, 96, 78, 28, 40, 40, 50, 84, 32, 37, 32, 34,
    64, 64, 64, 64, 64, 64, 64, 64, 64, 64, 34, 34, 84, 84, 84, 54,
    100, 69, 69, 70, 78, 64, 58, 78, 76, 30, 30, 66, 56, 87, 75, 79,
    61, 79, 70, 64, 62, 74, 69, 99, 69, 62, 69, 40, 34, 40, 84, 50,
    50, 62, 64, 55, 64, 62, 36, 64, 64, 28, 28, 58, 28, 98, 64, 62,
    64, 64, 42, 53, 40, 64, 60, 82, 60, 60, 53, 64, 34, 64, 84)
DEJAVU_SANS_BOLD_CEM = (
    35, 46, 53, 84, 70, 101, 88, 31, 46, 46, 53, 84, 38, 42, 38, 37,
    70, 70, 70, 70, 70, 70, 70, 70, 70, 70, 40, 40, 84, 84, 84, 59,
    100, 78, 77, 74, 84, 69, 69, 83, 84, 38, 38, 78, 64, 100, 84, 86,
    74, 86, 78, 73, 69, 82, 78, 111, 78, 73, 73, 46, 37, 46, 84, 50,
    50, 68, 72, 60, 72, 68, 44, 72, 72, 35, 35, 67, 35, 105, 72, 69,
    72, 72, 50, 60, 48, 72, 66, 93, 65, 66, 59, 72, 37, 72, 84)
FIRST_TABLE_CHAR = 32
OTHER_CHAR_EM, OTHER_CHAR_BOLD_EM = 1.0, 1.12

warnings_count = 0


def warn(message):
    global warnings_count
    warnings_count += 1
    print("render_mission: " + message, file=sys.stderr)


# ---------------------------------------------------------------------------------------------
# MOOS text helpers.

def split_outside_braces(text, sep=","):
    """Split at `sep` except inside {...}. Pieces are joined back while a brace is open."""
    pieces = text.split(sep)
    if "{" not in text:
        return pieces
    parts, pending, depth = [], None, 0
    for piece in pieces:
        pending = piece if pending is None else pending + sep + piece
        depth = max(0, depth + piece.count("{") - piece.count("}"))
        if depth == 0:
            parts.append(pending)
            pending = None
    if pending is not None:
        parts.append(pending)
    return parts


def key_values(text):
    """`a=1,b=2` -> {'a': '1', 'b': '2'} with lower-case keys; braces respected."""
    out = {}
    for piece in split_outside_braces(text):
        key, sep, value = piece.partition("=")
        if sep:
            out[key.strip().lower()] = value.strip()
    return out


def number(text):
    """A finite float from text, or None (never raises)."""
    if text is None:
        return None
    try:
        v = float(text)
    except ValueError:
        return None
    return v if math.isfinite(v) else None


def parse_point_list(body):
    """`x1,y1:x2,y2` -> [(x, y), ...], or None when a vertex is not two numbers."""
    points = []
    for vertex in body.split(":"):
        coords = vertex.split(",")
        if len(coords) < 2:
            return None
        x, y = number(coords[0]), number(coords[1])
        if x is None or y is None:
            return None
        points.append((x, y))
    return points or None


def parse_points(text):
    """`pts={x1,y1:x2,y2}` (anywhere in text) or `x1,y1:x2,y2` -> [(x, y), ...] or None."""
    start = text.find("pts")
    if start >= 0:
        open_brace = text.find("{", start)
        close_brace = text.find("}", open_brace + 1)
        if open_brace >= 0 and close_brace > open_brace and \
                text[start + 3:open_brace].strip() in ("=", ""):
            return parse_point_list(text[open_brace + 1:close_brace])
    return parse_point_list(text)


CSS_NAMES = {"lightblue", "green", "yellow", "white", "pink", "red", "blue", "orange", "black",
             "gray", "grey", "darkgreen", "lightgreen", "cyan", "magenta", "purple", "brown",
             "gold", "navy", "violet", "khaki", "salmon", "tan", "teal", "olive", "silver",
             "darkblue", "lightgray", "lightgrey", "darkgray", "darkgrey", "hotpink", "coral",
             "crimson", "turquoise", "lime", "maroon", "beige", "ivory", "orchid", "plum"}
GREY_WORD = re.compile(r"^gr[ae]y(\d{1,3})$")
HEX_WORD = re.compile(r"^hex:([0-9a-f]{2}),([0-9a-f]{2}),([0-9a-f]{2})$")
LETTERS_WORD = re.compile(r"^[a-z]+$")


@lru_cache(maxsize=256)  # a log repeats a handful of colour words thousands of times
def svg_colour(moos, fallback="#999999"):
    """A MOOS colour word (manual colour appendix) as an SVG colour."""
    if not moos:
        return fallback
    word = moos.strip().lower().replace("_", "")
    m = GREY_WORD.match(word)
    if m and int(m.group(1)) <= 100:
        level = round(int(m.group(1)) * 255 / 100)
        return "#%02x%02x%02x" % (level, level, level)
    m = HEX_WORD.match(word)
    if m:
        return "#" + "".join(m.groups())
    if word in ("invisible", "empty"):
        return "none"
    if LETTERS_WORD.match(word):
        return word if word in CSS_NAMES or len(word) > 2 else fallback
    return fallback


# ---------------------------------------------------------------------------------------------
# Inputs.

class Run:
    def __init__(self):
        self.log_name = None
        self.tracks = {}          # vehicle -> [(t, x, y, hdg, spd)]
        self.swaths = {}          # vehicle -> [(t, [(x, y)]*4, on)]
        self.widths = {}          # vehicle -> acked W
        self.circles = []         # dicts from VIEW_CIRCLE
        self.detection_values = []       # (value, place) of UHZ_DETECTION_REPORT, parsed if needed
        self.classification_values = []  # (value, place) of UHZ_HAZARD_REPORT, parsed if needed
        self.markers = {}         # label -> VIEW_MARKER fields
        self.region = None
        self.reports = []         # (source, [labels]) in log order
        self.evals = {}           # vehicle -> dict (latest)
        self.handovers = []       # (source, dest, object count)
        self.acks = {}            # vehicle -> latest UHZ_CONFIG_ACK fields


def read_hazard_file(path):
    objects, region = [], None
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
    except OSError as e:
        warn("cannot read hazard file %s: %s" % (path, e))
        return objects, region
    for n, raw in enumerate(lines, 1):
        line = raw.split("//", 1)[0].strip()
        if not line or "=" not in line:
            continue
        key, value = line.split("=", 1)
        key = key.strip().lower()
        if key == "region":
            region = parse_points(value)
            if region is None:
                warn("%s:%d: bad region '%s'" % (path, n, value.strip()))
        elif key == "hazard":
            kv = key_values(value)
            x, y = number(kv.get("x")), number(kv.get("y"))
            label = kv.get("label", "")
            if x is None or y is None or not label:
                warn("%s:%d: hazard line without x, y and label skipped" % (path, n))
                continue
            objects.append({"x": x, "y": y, "label": label,
                            "hazard": kv.get("type", "").lower() == "hazard",
                            "hr": number(kv.get("hr")), "color": kv.get("color"),
                            "shape": kv.get("shape"), "width": number(kv.get("width"))})
    return objects, region


def where(place):
    """A (path, line number) place as `path:line`."""
    return "%s:%d" % place


def on_node_report(run, t, value, place):
    # The fast path: MOOS writes NODE_REPORT keys in capitals and without braces, so the fields
    # are split without the brace check, case folding and stripping of key_values.
    fields = {}
    for piece in value.split(","):
        key, _sep, text = piece.partition("=")
        fields[key] = text
    name, x, y = fields.get("NAME"), fields.get("X"), fields.get("Y")
    hdg, spd = fields.get("HDG", fields.get("HEADING")), fields.get("SPD", fields.get("SPEED"))
    if name is None or x is None or y is None or "{" in value:   # other spellings, braces
        kv = key_values(value)
        name, x, y = kv.get("name"), kv.get("x"), kv.get("y")
        hdg, spd = kv.get("hdg", kv.get("heading")), kv.get("spd", kv.get("speed"))
    name = name.strip() if name else name
    x, y = number(x), number(y)
    if not name or x is None or y is None:
        warn("%s: NODE_REPORT without NAME, X and Y skipped" % where(place))
        return
    hdg, spd = number(hdg), number(spd)
    track = run.tracks.get(name)
    if track is None:
        track = run.tracks[name] = []
    if not track or track[-1][0] != t or track[-1][1] != x or track[-1][2] != y:
        track.append((t, x, y, hdg if hdg is not None else 0.0, spd if spd is not None else 0.0))


def on_view_polygon(run, t, value, place):
    # Only two polygons are drawn: the swaths, and the grader's region while none is known.
    swath = "sensor_swath_" in value
    if not swath and (run.region is not None or "search_region" not in value):
        return
    pts = parse_points(value)
    if pts is None:
        warn("%s: VIEW_POLYGON without points skipped" % where(place))
        return
    open_brace, close_brace = value.find("{"), value.rfind("}")
    rest = value[:open_brace] + value[close_brace + 1:] if 0 <= open_brace < close_brace else value
    kv = key_values(rest)
    label = kv.get("label", "")
    if label.startswith("sensor_swath_") and len(pts) == 4:
        on = kv.get("fill_color", "white").lower() != "red"
        run.swaths.setdefault(label[len("sensor_swath_"):], []).append((t, pts, on))
    elif label == "search_region" and run.region is None:
        run.region = pts


def on_config_ack(run, t, value, place):
    kv = key_values(value)
    w = number(kv.get("width"))
    if kv.get("vname") and w is not None:
        run.widths[kv["vname"]] = w
        run.acks[kv["vname"]] = kv


def on_handover(run, t, value, place):
    parts = value.split("#")
    header = {}
    for p in parts[:3]:
        header.update(key_values(p))
    if header.get("source") and header.get("dest"):
        run.handovers.append((header["source"], header["dest"], max(0, len(parts) - 3)))
    else:
        warn("%s: HAZARD_HANDOVER without source and dest skipped" % where(place))


def on_view_circle(run, t, value, place):
    kv = key_values(value)
    x, y = number(kv.get("x")), number(kv.get("y"))
    if x is None or y is None:
        warn("%s: VIEW_CIRCLE without x and y skipped" % where(place))
        return
    run.circles.append({"x": x, "y": y,
                        "radius": number(kv.get("radius")) or DETECTION_RADIUS_M,
                        "vertices": int(number(kv.get("vertices")) or 12),
                        "edge": kv.get("edge_color"), "fill": kv.get("fill_color"),
                        "edge_size": number(kv.get("edge_size")) or 1.0,
                        "transparency": number(kv.get("fill_transparency"))})


def on_detection_report(run, t, value, place):
    run.detection_values.append((value, place))


def on_hazard_report(run, t, value, place):
    run.classification_values.append((value, place))


def on_view_marker(run, t, value, place):
    kv = key_values(value)
    if kv.get("label"):
        run.markers[kv["label"]] = kv


def on_mission_params(run, t, value, place):
    if run.region is None and "search_region" in value:
        text = key_values(value).get("search_region")
        if text is not None:
            run.region = parse_points(text)


def on_hazardset_report(run, t, value, place):
    source, labels = "", []
    for part in value.split("#"):
        part = part.strip()
        if part.startswith("source"):
            source = part.split("=", 1)[-1].strip()
        elif part.startswith(("name", "transit_path_width", "search_region")):
            continue
        else:
            at = part.find("label=")
            if at >= 0:
                label = part[at + len("label="):].split(",", 1)[0].strip()
                if label:
                    labels.append(label)
    if source:
        run.reports.append((source, labels))
    else:
        warn("%s: HAZARDSET_REPORT without source skipped" % where(place))


def on_hazardset_eval(run, t, value, place):
    kv = key_values(value)
    if kv.get("vname"):
        run.evals[kv["vname"]] = kv
    else:
        warn("%s: HAZARDSET_EVAL without vname skipped" % where(place))


# The variables the picture draws; every other line is skipped after its first split.
HANDLERS = {
    "NODE_REPORT": on_node_report, "NODE_REPORT_LOCAL": on_node_report,
    "VIEW_POLYGON": on_view_polygon, "VIEW_CIRCLE": on_view_circle, "VIEW_MARKER": on_view_marker,
    "UHZ_DETECTION_REPORT": on_detection_report, "UHZ_HAZARD_REPORT": on_hazard_report,
    "UHZ_MISSION_PARAMS": on_mission_params, "HAZARD_HANDOVER": on_handover,
    "HAZARDSET_REPORT": on_hazardset_report, "HAZARDSET_EVAL": on_hazardset_eval,
}
CONFIG_ACK_PREFIX = "UHZ_CONFIG_ACK"   # UHZ_CONFIG_ACK and UHZ_CONFIG_ACK_<V> carry the same


def warn_malformed(path, n):
    warn("%s:%d: malformed line skipped (expected TIME VARIABLE SOURCE VALUE)" % (path, n))


def read_alog(path, run):
    """Stream the log once: TIME VARIABLE SOURCE VALUE per line, `%%` lines are the header."""
    try:
        f = open(path, encoding="utf-8", errors="replace", newline="\n")
    except OSError as e:
        warn("cannot read log %s: %s" % (path, e))
        return
    with f:
        for n, line in enumerate(f, 1):
            parts = line.split(None, 3)
            if not parts:
                continue
            if parts[0].startswith("%%"):
                if "LOG FILE:" in line:
                    name = line.split("LOG FILE:", 1)[1].split()
                    if name:
                        run.log_name = name[0]
                continue
            if len(parts) < 3:
                warn_malformed(path, n)
                continue
            var = parts[1]
            handler = HANDLERS.get(var)
            if handler is None:
                if not var.startswith(CONFIG_ACK_PREFIX):
                    continue            # not drawn: its time and value are never parsed
                handler = on_config_ack
            t = number(parts[0])
            if t is None:
                warn_malformed(path, n)
                continue
            value = parts[3].rstrip() if len(parts) > 3 else ""
            place = (path, n)   # formatted only for a warning
            try:
                handler(run, t, value, place)
            except Exception as e:  # one bad value never stops the picture
                warn("%s: %s value skipped (%s)" % (where(place), var, e))


def report_positions(values, with_type):
    """UHZ_DETECTION_REPORT / UHZ_HAZARD_REPORT values -> [(x, y, type)]; bad ones named."""
    out = []
    for value, place in values:
        kv = key_values(value)
        x, y = number(kv.get("x")), number(kv.get("y"))
        if x is None or y is None:
            warn("%s: report without x and y skipped" % where(place))
            continue
        out.append((x, y, kv.get("type", "") if with_type else ""))
    return out


def read_summary(path, run):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        warn("cannot read summary %s: %s" % (path, e))
        return None
    if not isinstance(data, dict):
        warn("summary %s is not a JSON object" % path)
        return None
    evals = data.get("evals", data.get("scores", []))
    if isinstance(evals, dict):
        evals = [dict(v, vname=k) if isinstance(v, dict) else v for k, v in evals.items()]
    for e in evals if isinstance(evals, list) else []:
        if isinstance(e, str):
            kv = key_values(e)
        elif isinstance(e, dict):
            kv = {str(k).lower(): str(v) for k, v in e.items()}
        else:
            kv = {}
        if kv.get("vname") and kv["vname"] not in run.evals:
            run.evals[kv["vname"]] = kv
    return data


# ---------------------------------------------------------------------------------------------
# Geometry.

def turn_rate_flags(track):
    """Per track sample: was the sensor on (spec 8.2 turn rate over 2 s, speed limit)?

    The turn inside the window [j, i] is turned[i] - turned[j], with turned[] the running sum of
    the absolute heading changes; j only moves forward, so the whole track costs O(n)."""
    flags, turned = [], []
    total_deg, last_hdg, j = 0.0, None, 0
    for i, (t, _x, _y, hdg, spd) in enumerate(track):
        if last_hdg is not None:
            total_deg += abs((hdg - last_hdg + 180.0) % 360.0 - 180.0)
        last_hdg = hdg
        turned.append(total_deg)
        while t - track[j][0] >= TURN_WINDOW_S:
            j += 1
        span_s = t - track[j][0]
        rate_dps = (total_deg - turned[j]) / span_s if span_s > 0 else 0.0
        flags.append(rate_dps <= SENSOR_MAX_TURN_RATE_DPS and spd <= SENSOR_MAX_SPEED_MPS)
    return flags


class View:
    """Map metres -> viewport pixels, preserving aspect, north up."""

    def __init__(self, points):
        xs = [p[0] for p in points] or [0.0]
        ys = [p[1] for p in points] or [0.0]
        self.x0, self.x1 = min(xs), max(xs)
        self.y0, self.y1 = min(ys), max(ys)
        pad = max(self.x1 - self.x0, self.y1 - self.y0, 50.0) * 0.06
        self.x0 -= pad
        self.x1 += pad
        self.y0 -= pad
        self.y1 += pad
        span = max(self.x1 - self.x0, self.y1 - self.y0)
        self.scale = min(MAP_W, MAP_H) / span
        cx, cy = (self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2
        self.ox = MAP_X + MAP_W / 2 - cx * self.scale
        self.oy = MAP_Y + MAP_H / 2 + cy * self.scale

    def px(self, x, y):
        return self.ox + x * self.scale, self.oy - y * self.scale

    def pts(self, points):
        return " ".join("%.1f,%.1f" % self.px(x, y) for x, y in points)


def regular_polygon(cx, cy, radius, vertices):
    """Vertices of a regular polygon, first vertex to the north (as the viewer's circles)."""
    return [(cx + radius * math.sin(2 * math.pi * k / vertices),
             cy + radius * math.cos(2 * math.pi * k / vertices)) for k in range(vertices)]


def marker_points(shape, x, y, w):
    h = w / 2.0
    if shape == "square":
        return [(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)]
    if shape == "diamond":
        return [(x, y + h), (x + h, y), (x, y - h), (x - h, y)]
    if shape == "circle":
        return regular_polygon(x, y, h, 16)
    return [(x, y + h), (x + h, y - h), (x - h, y - h)]  # triangle (and unknown shapes)


def nice_length(target):
    exp = 10 ** math.floor(math.log10(target))
    for m in (5, 2, 1):
        if m * exp <= target:
            return m * exp
    return exp


def thin_points(points, min_step):
    """Drop points closer than min_step (along x plus along y) to the last kept one; the first
    and the last point are always kept."""
    if not points:
        return []
    kept = [points[0]]
    lx, ly = points[0]
    for p in points:
        if abs(p[0] - lx) + abs(p[1] - ly) >= min_step:
            kept.append(p)
            lx, ly = p
    if kept[-1] is not points[-1]:
        kept.append(points[-1])
    return kept


def simplify(points, tolerance):
    """Douglas-Peucker: the fewest points whose polyline stays within tolerance of the input."""
    if len(points) < 3:
        return list(points)
    keep = [False] * len(points)
    keep[0] = keep[-1] = True
    stack = [(0, len(points) - 1)]
    while stack:
        first, last = stack.pop()
        ax, ay = points[first]
        bx, by = points[last]
        dx, dy = bx - ax, by - ay
        length = math.hypot(dx, dy)
        worst, worst_at = -1.0, first
        for i in range(first + 1, last):
            px, py = points[i]
            if length > 0:
                d = abs(dy * (px - ax) - dx * (py - ay)) / length
            else:
                d = math.hypot(px - ax, py - ay)
            if d > worst:
                worst, worst_at = d, i
        if worst > tolerance:
            keep[worst_at] = True
            stack.append((first, worst_at))
            stack.append((worst_at, last))
    return [p for p, k in zip(points, keep) if k]


def pixel_path(view, points_m):
    """Metres -> pixels, thinned (in metres, before the conversion: most points go) and
    simplified to what a pixel shows."""
    step_m = TRACK_STEP_PX / view.scale
    kept = thin_points(points_m, step_m)
    scale, ox, oy = view.scale, view.ox, view.oy
    return simplify([(ox + x * scale, oy - y * scale) for x, y in kept], SIMPLIFY_TOLERANCE_PX)


def swath_strips(swaths):
    """Sensor-on swath rectangles -> strips [[centres, across_m, along_m, corners]].

    Consecutive rectangles of one setting that touch or overlap become one strip through their
    centres; `corners` (of the strip's last rectangle) is drawn instead of a strip that does not
    move, such as a vehicle waiting at its start. The along-track side is the one
    more parallel to the motion from the previous rectangle (first rectangle: the corner order
    of our sensor, src/hazard/swath.cpp, whose first side runs along the track)."""
    strips, current, last_centre = [], None, None
    for (_t, pts, on) in swaths:
        cx = sum(p[0] for p in pts) / 4.0
        cy = sum(p[1] for p in pts) / 4.0
        side_a = (pts[1][0] - pts[0][0], pts[1][1] - pts[0][1])
        side_b = (pts[2][0] - pts[1][0], pts[2][1] - pts[1][1])
        len_a, len_b = math.hypot(*side_a), math.hypot(*side_b)
        along_m, across_m = len_a, len_b
        if last_centre is not None and len_a > 0 and len_b > 0:
            mx, my = cx - last_centre[0], cy - last_centre[1]
            if mx or my:
                if abs(side_b[0] * mx + side_b[1] * my) / len_b > \
                        abs(side_a[0] * mx + side_a[1] * my) / len_a:
                    along_m, across_m = len_b, len_a
        joins = (current is not None and on and
                 math.hypot(cx - last_centre[0], cy - last_centre[1])
                 <= max(along_m, current[2]) + SWATH_JOIN_SLACK_M and
                 abs(across_m - current[1]) <= SWATH_WIDTH_CHANGE * max(across_m, current[1]))
        if joins:
            current[0].append((cx, cy))
            current[3] = pts
        else:
            if current is not None:
                strips.append(current)
            current = [[(cx, cy)], across_m, along_m, pts] if on else None
        last_centre = (cx, cy)
    if current is not None:
        strips.append(current)
    return strips


def extend_ends(centres, along_m):
    """The strip's centre line, lengthened by half a swath at each end (the rectangles' ends)."""
    if len(centres) < 2:
        return centres
    def step(a, b):
        d = math.hypot(b[0] - a[0], b[1] - a[1])
        return ((b[0] - a[0]) / d * along_m / 2, (b[1] - a[1]) / d * along_m / 2) if d else (0, 0)
    head = step(centres[1], centres[0])
    tail = step(centres[-2], centres[-1])
    return ([(centres[0][0] + head[0], centres[0][1] + head[1])] + centres +
            [(centres[-1][0] + tail[0], centres[-1][1] + tail[1])])


# ---------------------------------------------------------------------------------------------
# Text fitting.

def text_width_px(text, font_px, bold=False):
    """An upper estimate of the rendered width of text (see DEJAVU_SANS_CEM)."""
    table = DEJAVU_SANS_BOLD_CEM if bold else DEJAVU_SANS_CEM
    other_cem = 100 * (OTHER_CHAR_BOLD_EM if bold else OTHER_CHAR_EM)
    cem = 0.0
    for c in text:
        code = ord(c) - FIRST_TABLE_CHAR
        cem += table[code] if 0 <= code < len(table) else other_cem
    return cem / 100.0 * font_px


def fit_text(text, max_width_px, font_px, min_font_px, bold=False):
    """(text, font_px) that fits max_width_px: a smaller font first, then an ellipsis."""
    size = float(font_px)
    while size > min_font_px and text_width_px(text, size, bold) > max_width_px:
        size = max(float(min_font_px), size - 0.5)
    if text_width_px(text, size, bold) <= max_width_px:
        return text, size
    while len(text) > 1 and text_width_px(text + "\u2026", size, bold) > max_width_px:
        text = text[:-1]
    return text.rstrip() + "\u2026", size


def svg_text(x, y, text, font_px, fill, max_width_px, min_font_px=None, bold=False, extra=""):
    """A <text> element fitted to max_width_px (font shrinks to min_font_px, then an ellipsis)."""
    fitted, size = fit_text(text, max_width_px, font_px, min_font_px or font_px * 0.8, bold)
    return ('<text x="%.1f" y="%.1f" font-size="%g" fill="%s"%s%s>%s</text>'
            % (x, y, size, fill, ' font-weight="bold"' if bold else "", extra, escape(fitted)))


# ---------------------------------------------------------------------------------------------
# Level of detail.

class Detail:
    """What the picture draws for this many objects (module contract, "Two levels of detail")."""

    def __init__(self, mode, auto, view, objects, region):
        self.mode = mode
        self.auto = auto            # chosen from the object count, not by --detail
        self.field = mode == "field"
        self.labels = not self.field
        self.track_width_px = FIELD_TRACK_WIDTH_PX if self.field else OBJECTS_TRACK_WIDTH_PX
        self.swath_opacity = FIELD_SWATH_OPACITY if self.field else SWATH_OPACITY
        spacing_px = mean_spacing_px(view, objects, region)
        self.benign_px = min(FIELD_MARKER_MAX_PX, max(
            FIELD_MARKER_MIN_PX, FIELD_MARKER_SPACING_FRACTION * spacing_px))
        self.hazard_px = self.benign_px * FIELD_HAZARD_SCALE
        self.dot_px = max(1.5, self.benign_px * FIELD_CUE_DOT_FRACTION)
        self.ring_px = self.hazard_px * FIELD_MISSED_RING_FRACTION
        self.counts = {}

    def count_field(self, objects, cues, missed):
        """The numbers the field legend shows beside its symbols."""
        hazards = sum(1 for o in objects if o["hazard"])
        self.counts = {"hazard": hazards, "benign": len(objects) - hazards, "missed": len(missed)}
        for cls, _colour in CUE_DOTS:
            self.counts[cls] = 0
        for cls in cues.values():
            self.counts[cls] += 1


def choose_mode(requested, objects):
    if requested in ("objects", "field"):
        return requested
    return "field" if len(objects) > DETAIL_MAX_OBJECTS else "objects"


def mean_spacing_px(view, objects, region):
    """Mean distance between objects on the map: sqrt(area / count), area of region or extent."""
    if not objects:
        return MAP_W
    if region and len(region) >= 3:
        area_m2 = abs(sum(a[0] * b[1] - b[0] * a[1]
                          for a, b in zip(region, region[1:] + region[:1]))) / 2
    else:
        xs = [o["x"] for o in objects]
        ys = [o["y"] for o in objects]
        area_m2 = (max(xs) - min(xs)) * (max(ys) - min(ys))
    if area_m2 <= 0:
        return MAP_W
    return math.sqrt(area_m2 / len(objects)) * view.scale


# ---------------------------------------------------------------------------------------------
# Drawing the map.

def render(run, objects, hazard_region, opts):
    out = []
    w = out.append
    region = hazard_region or run.region
    vehicles = sorted(set(run.tracks) | set(run.swaths))
    colour = {v: vehicle_colour(i) for i, v in enumerate(vehicles)}

    extent = [(o["x"], o["y"]) for o in objects] + list(region or [])
    for track in run.tracks.values():
        extent += [(p[1], p[2]) for p in track]
    view = View(extent)
    detail = Detail(choose_mode(opts.detail, objects), opts.detail == "auto", view, objects,
                    region)
    circles = run.circles or derived_circles(run)
    final = run.reports[-1] if run.reports else None

    w('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" '
      'font-family="DejaVu Sans, Arial, sans-serif" data-detail="%s">'
      % (CANVAS_W, CANVAS_H, CANVAS_W, CANVAS_H, detail.mode))
    w('<rect x="0" y="0" width="%d" height="%d" fill="#f4f4f0"/>' % (CANVAS_W, CANVAS_H))
    title = opts.title or ("Hazard search: " + (run.log_name or os.path.basename(opts.alog or "")))
    w(svg_text(MAP_X, 38, title, TITLE_FONT_PX, "#222", CANVAS_W - 2 * MAP_X, TITLE_MIN_FONT_PX,
               bold=True, extra=' class="title"'))
    w('<clipPath id="map"><rect x="%d" y="%d" width="%d" height="%d"/></clipPath>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H))
    w('<rect class="map" x="%d" y="%d" width="%d" height="%d" fill="%s"/>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H, MAP_BACKGROUND))
    w('<g clip-path="url(#map)">')
    if region:   # the fill under the coverage, the outline over it
        w('<polygon class="region" points="%s" fill="#24364a" stroke="none"/>' % view.pts(region))
    draw_coverage(w, run, vehicles, colour, view, detail)
    if region:
        w('<polygon class="region-outline" points="%s" fill="none" stroke="#b0b0b0" '
          'stroke-width="2" stroke-dasharray="8,5"/>' % view.pts(region))
    draw_tracks(w, run, vehicles, colour, view, detail)
    if detail.field:
        cues = latest_cues(circles)
        missed = missed_hazards(final, objects) if final else []
        detail.count_field(objects, cues, missed)
        draw_objects_field(w, run, objects, view, detail, opts)
        draw_cues_field(w, cues, view, detail)
        draw_report_field(w, missed, view, detail)
    else:
        draw_objects(w, run, objects, view, opts)
        draw_cues(w, circles, view)
        draw_report(w, final, objects, view)
    draw_vehicle_ends(w, run, vehicles, colour, view)
    draw_scale_and_north(w, view)
    w('</g>')
    w('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#555" stroke-width="1"/>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H))
    if not objects and not run.tracks:
        w('<text x="%d" y="%d" font-size="20" fill="#dddddd" text-anchor="middle">'
          'no objects and no tracks in the inputs</text>' % (MAP_X + MAP_W / 2, MAP_Y + MAP_H / 2))
    draw_panel(w, run, final, objects, vehicles, colour, opts, detail)
    w('</svg>')
    return "\n".join(out) + "\n"


def vehicle_colour(index):
    """The palette first; past it, hues a golden angle apart (distinct for any count)."""
    if index < len(VEHICLE_COLOURS):
        return VEHICLE_COLOURS[index]
    hue = ((index - len(VEHICLE_COLOURS)) * GOLDEN_ANGLE_DEG + 20.0) % 360.0 / 360.0
    r, g, b = colorsys.hsv_to_rgb(hue, 0.55, 1.0)
    return "#%02x%02x%02x" % (round(r * 255), round(g * 255), round(b * 255))


def is_light(colour):
    """True for a #rrggbb colour too light to read on the light panel without a dark outline."""
    if not (colour.startswith("#") and len(colour) == 7):
        return False
    r, g, b = (int(colour[i:i + 2], 16) / 255.0 for i in (1, 3, 5))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b > LIGHT_LUMINANCE


def name_outline(colour):
    """SVG attributes that make a vehicle's name readable on the light panel."""
    if is_light(colour):
        return ' stroke="%s" stroke-width="2.5" paint-order="stroke"' % MAP_BACKGROUND
    return ' stroke="#444" stroke-width="0.3"'


def draw_coverage(w, run, vehicles, colour, view, detail):
    """Swath coverage: opaque strips in a translucent group per vehicle, so overlaps of one
    vehicle's passes do not darken."""
    for v in vehicles:
        w('<g class="swath" data-vehicle="%s" opacity="%.2f" fill="%s" stroke="none">'
          % (escape(v), detail.swath_opacity, colour[v]))
        if run.swaths.get(v):
            for centres, across_m, along_m, corners in swath_strips(run.swaths[v]):
                if not draw_strip(w, view, extend_ends(centres, along_m), across_m, colour[v]):
                    w('<polygon points="%s"/>' % view.pts(corners))
        elif run.tracks.get(v) and run.widths.get(v):
            track = run.tracks[v]
            segment = []
            for p, on in zip(track, turn_rate_flags(track)):
                if on:
                    segment.append((p[1], p[2]))
                elif segment:
                    draw_strip(w, view, segment, 2 * run.widths[v], colour[v])
                    segment = []
            draw_strip(w, view, segment, 2 * run.widths[v], colour[v])
        w('</g>')


def draw_strip(w, view, centres_m, width_m, stroke):
    """A strip of width_m along centres_m; False (nothing drawn) when it is shorter than a pixel."""
    if len(centres_m) < 2:
        return False
    points = pixel_path(view, centres_m)
    if len(points) < 2 or all(abs(p[0] - points[0][0]) + abs(p[1] - points[0][1]) < TRACK_STEP_PX
                              for p in points):
        return False
    w('<polyline points="%s" fill="none" stroke="%s" stroke-width="%.1f" stroke-linecap="butt" '
      'stroke-linejoin="round"/>'
      % (" ".join("%.1f,%.1f" % p for p in points), stroke, width_m * view.scale))
    return True


def draw_tracks(w, run, vehicles, colour, view, detail):
    for v in vehicles:
        points = pixel_path(view, [(p[1], p[2]) for p in run.tracks.get(v, [])])
        if len(points) > 1:
            w('<polyline class="track" data-vehicle="%s" points="%s" fill="none" stroke="%s" '
              'stroke-width="%.1f" stroke-linejoin="round"/>'
              % (escape(v), " ".join("%.1f,%.1f" % p for p in points), colour[v],
                 detail.track_width_px))


VEHICLE_NAME_PX = 14
NAME_OFFSET_PX = 8          # from the end dot to the name
NAME_CANDIDATES = ((1, -1), (1, 1), (-1, -1), (-1, 1))   # right-above, right-below, left-...


def boxes_overlap(a, b):
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


def draw_vehicle_ends(w, run, vehicles, colour, view):
    """Each vehicle's last position and its name, on top of everything else in the map. A name
    takes the first place beside its dot that is inside the map and clear of the other names,
    the north arrow and the scale bar; with no such place only the dot is drawn (the panel
    names every vehicle in its colour)."""
    taken = [NORTH_PLATE_BOX, scale_plate_box(view)]
    for v in vehicles:
        track = run.tracks.get(v)
        if not track:
            continue
        x, y = view.px(track[-1][1], track[-1][2])
        w('<circle class="vehicle-end" cx="%.1f" cy="%.1f" r="5" fill="%s" stroke="#000"/>'
          % (x, y, colour[v]))
        name_px = text_width_px(v, VEHICLE_NAME_PX, bold=True)
        for side, above in NAME_CANDIDATES:
            left = x + NAME_OFFSET_PX if side > 0 else x - NAME_OFFSET_PX - name_px
            baseline = y - NAME_OFFSET_PX if above < 0 else y + NAME_OFFSET_PX + VEHICLE_NAME_PX
            box = (left, baseline - VEHICLE_NAME_PX, name_px, VEHICLE_NAME_PX + 3)
            inside = (box[0] >= MAP_X + 2 and box[0] + box[2] <= MAP_X + MAP_W - 2 and
                      box[1] >= MAP_Y + 2 and box[1] + box[3] <= MAP_Y + MAP_H - 2)
            if inside and not any(boxes_overlap(box, other) for other in taken):
                taken.append(box)
                w('<text class="vehicle-name" x="%.1f" y="%.1f" font-size="%d" '
                  'font-weight="bold" fill="%s" stroke="%s" stroke-width="3" '
                  'paint-order="stroke"%s>%s</text>'
                  % (x + NAME_OFFSET_PX * side, baseline, VEHICLE_NAME_PX, colour[v],
                     MAP_BACKGROUND, ' text-anchor="end"' if side < 0 else "", escape(v)))
                break


def object_style(run, o, opts):
    """(shape, SVG colour, width_m, fill opacity) of an object: VIEW_MARKER, hazard file, options."""
    style = run.markers.get(o["label"], {})
    hazard = o["hazard"]
    shape = (style.get("type") or o["shape"] or
             (opts.hazard_shape if hazard else opts.benign_shape)).lower()
    col = svg_colour(style.get("primary_color") or o["color"] or
                     (opts.hazard_color if hazard else opts.benign_color))
    width = number(style.get("width")) or o["width"] or DEFAULT_MARKER_WIDTH_M
    opacity = 1.0
    if not hazard:
        # Spec 5.4: a benign marker's fill_transparency (the viewer's alpha) is 1 - hr, 0.5
        # without hr. The edge is always drawn, so a fully clear fill still shows the shape.
        alpha = number(style.get("fill_transparency"))
        if alpha is None:
            alpha = 1.0 - (o["hr"] if o["hr"] is not None else 0.5)
        opacity = min(1.0, max(0.0, alpha))
    return shape, col, width, opacity


def draw_objects(w, run, objects, view, opts):
    """Objects mode: one marker and one label per object."""
    for o in objects:
        shape, col, width, opacity = object_style(run, o, opts)
        width = max(width * view.scale, MIN_MARKER_PX) / view.scale
        w('<polygon class="marker %s" data-label="%s" points="%s" fill="%s" fill-opacity="%.2f" '
          'stroke="%s" stroke-width="1.5"/>'
          % ("hazard" if o["hazard"] else "benign", escape(o["label"]),
             view.pts(marker_points(shape, o["x"], o["y"], width)), col, opacity, col))
        lx, ly = view.px(o["x"], o["y"])
        offset = DETECTION_RADIUS_M * view.scale * 0.75 + 3  # beside the radius-10 cues
        w('<text class="label" x="%.1f" y="%.1f" font-size="11" fill="#e0e0e0">%s</text>'
          % (lx + offset, ly + offset + 8, escape(o["label"])))


def marker_path_template(shape, size_px):
    """Relative SVG path of a marker of size_px, drawn from its top-left anchor point."""
    h = size_px / 2.0
    if shape == "square":
        return (-h, -h), "h%.1fv%.1fh%.1fz" % (2 * h, 2 * h, -2 * h)
    if shape == "diamond":
        return (0.0, -h), "l%.1f %.1fl%.1f %.1fl%.1f %.1fz" % (h, h, -h, h, -h, -h)
    if shape == "circle":
        return (-h, 0.0), "a%.1f %.1f 0 1 0 %.1f 0a%.1f %.1f 0 1 0 %.1f 0z" % (
            h, h, 2 * h, h, h, -2 * h)
    return (0.0, -h), "l%.1f %.1fh%.1fz" % (h, 2 * h, -2 * h)  # triangle (and unknown shapes)


def draw_objects_field(w, run, objects, view, detail, opts):
    """Field mode: markers sized to the object spacing, one <path> per (kind, shape, colour,
    fill alpha binned to OPACITY_STEP); benign objects first, hazards on top."""
    groups = {}
    for o in objects:
        shape, col, _width, opacity = object_style(run, o, opts)
        key = (o["hazard"], shape, col, round(opacity / OPACITY_STEP) * OPACITY_STEP)
        groups.setdefault(key, []).append(o)
    for key in sorted(groups, key=lambda k: (k[0], k[1], k[2], k[3])):
        hazard, shape, col, opacity = key
        size = detail.hazard_px if hazard else detail.benign_px
        (ax, ay), tail = marker_path_template(shape, size)
        d = "".join("M%.1f %.1f%s" % (px + ax, py + ay, tail)
                    for px, py in (view.px(o["x"], o["y"]) for o in groups[key]))
        w('<path class="markers %s" data-count="%d" d="%s" fill="%s" fill-opacity="%.1f" '
          'stroke="%s" stroke-width="%.1f" stroke-opacity="%.2f"/>'
          % ("hazard" if hazard else "benign", len(groups[key]), d, col, opacity, col,
             1.0 if hazard else 0.6, 1.0 if hazard else 0.45))


def draw_cues(w, circles, view):
    """Objects mode: the viewer's cues as posted (12-vertex circles, pentagons)."""
    for c in circles:
        vertices = max(3, c["vertices"])
        kind = "classification" if vertices == 5 else "detection"
        edge, fill = svg_colour(c["edge"], "white"), svg_colour(c["fill"], "white")
        # The viewer uses `fill_transparency` as the fill's alpha (0 clear, 1 solid).
        fill_opacity = c["transparency"] if c["transparency"] is not None else 0.3
        cls = kind
        if kind == "classification":
            cls += " hazard" if (c["edge"] or "").lower() in ("yellow", "red") else " benign"
        if (c["fill"] or "").lower() == "pink":
            cls += " pink"
        w('<polygon class="%s" points="%s" fill="%s" fill-opacity="%.2f" stroke="%s" '
          'stroke-width="%.1f"/>'
          % (cls, view.pts(regular_polygon(c["x"], c["y"], c["radius"], vertices)), fill,
             max(0.0, min(1.0, fill_opacity)), edge, max(1.0, c["edge_size"] * 1.5)))


# Field mode cue dots: (class, colour) by the latest cue of a position, in drawing order (the
# rarer and more telling classes on top).
CUE_DOTS = [("detection", "white"), ("classification benign", "#7dff7d"),
            ("classification hazard", "yellow"), ("pink", "pink")]


def latest_cues(circles):
    """Per cued position, the class of its latest cue; a classification outranks a detection."""
    latest = {}   # (x, y) -> (stage: 0 detection / 1 classification, class)
    for c in circles:
        key = (round(c["x"], 2), round(c["y"], 2))
        pink = (c["fill"] or "").lower() == "pink"
        if c["vertices"] == 5:
            hazard = (c["edge"] or "").lower() in ("yellow", "red")
            latest[key] = (1, "pink" if pink else (
                "classification hazard" if hazard else "classification benign"))
        elif latest.get(key, (0, ""))[0] == 0:
            latest[key] = (0, "pink" if pink else "detection")
    return {key: cls for key, (_stage, cls) in latest.items()}


def draw_cues_field(w, cues, view, detail):
    """Field mode: one dot per cued object, coloured by its latest cue (zero-length round-capped
    path segments: the shortest SVG for many dots)."""
    by_class = {}
    for (x, y), cls in cues.items():
        by_class.setdefault(cls, []).append(view.px(x, y))
    for cls, col in CUE_DOTS:
        points = by_class.get(cls)
        if points:
            w('<path class="cues %s" data-count="%d" d="%s" stroke="%s" stroke-width="%.1f" '
              'stroke-linecap="round" fill="none"/>'
              % (cls, len(points), "".join("M%.1f %.1fh0" % p for p in points), col,
                 detail.dot_px))


def draw_report(w, final, objects, view):
    """Objects mode: dashed rings on the reported objects, red rings on missed hazards."""
    if not final:
        return
    reported = set(final[1])
    by_label = {o["label"]: o for o in objects}
    for label in final[1]:
        o = by_label.get(label)
        if o:
            x, y = view.px(o["x"], o["y"])
            w('<circle class="reported" cx="%.1f" cy="%.1f" r="%.1f" fill="none" '
              'stroke="#ffffff" stroke-width="2" stroke-dasharray="5,3"/>'
              % (x, y, REPORT_RING_M * view.scale))
    for o in objects:
        if o["hazard"] and o["label"] not in reported:
            x, y = view.px(o["x"], o["y"])
            w('<circle class="missed" cx="%.1f" cy="%.1f" r="%.1f" fill="none" '
              'stroke="#ff3030" stroke-width="3"/>' % (x, y, REPORT_RING_M * view.scale * 1.15))


def missed_hazards(final, objects):
    """The hazards of the ground truth that the report `final` (source, labels) left out."""
    reported = set(final[1])
    return [o for o in objects if o["hazard"] and o["label"] not in reported]


def draw_report_field(w, missed, view, detail):
    """Field mode: red rings around the hazards the last report missed (the reported set is
    summed up in the panel: thousands of rings would hide the field)."""
    if missed:
        r = detail.ring_px
        d = "".join("M%.1f %.1fa%.1f %.1f 0 1 0 %.1f 0a%.1f %.1f 0 1 0 %.1f 0"
                    % (x - r, y, r, r, 2 * r, r, r, -2 * r)
                    for x, y in (view.px(o["x"], o["y"]) for o in missed))
        w('<path class="missed" data-count="%d" d="%s" fill="none" stroke="#ff3030" '
          'stroke-width="1.8"/>' % (len(missed), d))


def derived_circles(run):
    """D19 cues rebuilt from the reports when the log has no VIEW_CIRCLE postings."""
    circles = [{"x": x, "y": y, "radius": DETECTION_RADIUS_M, "vertices": 12, "edge": "white",
                "fill": "white", "edge_size": 1.0, "transparency": 0.7}
               for (x, y, _type) in report_positions(run.detection_values, False)]
    for (x, y, typ) in report_positions(run.classification_values, True):
        colour = "yellow" if typ == "hazard" else "green"
        circles.append({"x": x, "y": y, "radius": DETECTION_RADIUS_M, "vertices": 5, "edge": colour,
                        "fill": colour, "edge_size": 1.0, "transparency": 0.7})
    return circles


SCALE_BAR_X, SCALE_BAR_Y = MAP_X + 20, MAP_Y + MAP_H - 25   # left end and top of the bar
NORTH_X, NORTH_Y = MAP_X + MAP_W - 40, MAP_Y + 30             # the arrow's centre
NORTH_PLATE_BOX = (NORTH_X - 18, NORTH_Y - 26, 36, 64)         # x, y, width, height


def scale_bar_length_m(view):
    return nice_length(MAP_W * 0.25 / view.scale)


def scale_label(length_m):
    return ("%g m" % length_m) if length_m < 1000 else ("%g km" % (length_m / 1000))


def scale_plate_box(view):
    length_m = scale_bar_length_m(view)
    half_label_px = text_width_px(scale_label(length_m), 14) / 2
    return (SCALE_BAR_X - 10, SCALE_BAR_Y - 24, length_m * view.scale + half_label_px + 18, 40)


def draw_scale_and_north(w, view):
    """A scale bar (1, 2 or 5 x 10^k m, about a quarter of the map) and a north arrow, each on a
    translucent plate so that they read over a dense field."""
    length_m = scale_bar_length_m(view)
    length_px = length_m * view.scale
    x0, y0 = SCALE_BAR_X, SCALE_BAR_Y
    w('<g class="scale-bar">')
    w('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" rx="4" fill="%s" fill-opacity="0.75"/>'
      % (scale_plate_box(view) + (MAP_BACKGROUND,)))
    w('<rect x="%.1f" y="%.1f" width="%.1f" height="8" fill="#ffffff"/>' % (x0, y0, length_px / 2))
    w('<rect x="%.1f" y="%.1f" width="%.1f" height="8" fill="none" stroke="#ffffff"/>'
      % (x0, y0, length_px))
    w('<text x="%.1f" y="%.1f" font-size="14" fill="#ffffff">0</text>' % (x0 - 4, y0 - 6))
    w('<text x="%.1f" y="%.1f" font-size="14" fill="#ffffff" text-anchor="middle">%s</text>'
      % (x0 + length_px, y0 - 6, scale_label(length_m)))
    w('</g>')
    nx, ny = NORTH_X, NORTH_Y
    w('<g class="north-arrow">')
    w('<rect x="%d" y="%d" width="%d" height="%d" rx="4" fill="%s" fill-opacity="0.75"/>'
      % (NORTH_PLATE_BOX + (MAP_BACKGROUND,)))
    w('<polygon points="%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f" fill="#ffffff" stroke="#000"/>'
      % (nx, ny - 20, nx + 11, ny + 14, nx, ny + 6, nx - 11, ny + 14))
    w('<text x="%.1f" y="%.1f" font-size="16" font-weight="bold" fill="#ffffff" '
      'text-anchor="middle">N</text>' % (nx, ny + 34))
    w('</g>')


# ---------------------------------------------------------------------------------------------
# Drawing the panel: score table, summary lines and legend, as rows of known height.

class Row:
    """One panel row: its height and a function that draws it with its top at y."""

    def __init__(self, height, draw):
        self.height = height
        self.draw = draw


def text_row(text, font_px, fill, height, indent=0, bold=False, cls=""):
    extra = ' class="%s"' % cls if cls else ""
    return Row(height, lambda y: [svg_text(PANEL_X + indent, y + font_px, text, font_px, fill,
                                           PANEL_W - indent, bold=bold, extra=extra)])


def heading_row(text):
    return Row(30, lambda y: ['<text x="%d" y="%d" font-size="18" font-weight="bold" fill="#222">'
                              '%s</text>' % (PANEL_X, y + 16, escape(text))])


def setting_text(ack):
    """A vehicle's acknowledged sensor setting (UHZ_CONFIG_ACK fields), "?" for a missing one."""
    return "swath %s m, pd %s, pfa %s, pclass %s" % (
        ack.get("width", "?"), ack.get("pd", "?"), ack.get("pfa", "?"), ack.get("pclass", "?"))


def score_rows_full(run, colour, vehicles_shown):
    """Four lines per vehicle: score, sensor setting, found/missed/false alarms, penalty split."""
    rows = []
    for vname in vehicles_shown:
        e = run.evals[vname]

        def score_line(y, vname=vname, e=e):
            name, name_size = fit_text(vname, PANEL_W * 0.6, 15, 11, bold=True)
            rest = ": %s / 100" % e.get("norm_score", "?")
            fitted, size = fit_text(rest, PANEL_W - text_width_px(name, name_size, bold=True),
                                    15, 12)
            col = colour.get(vname, "#222")
            return ['<text class="score" data-vehicle="%s" x="%d" y="%d" font-size="15" '
                    'fill="#222"><tspan font-weight="bold" font-size="%g" fill="%s"%s>%s</tspan>'
                    '<tspan font-size="%g">%s</tspan></text>'
                    % (escape(vname), PANEL_X, y + 14, name_size, col, name_outline(col),
                       escape(name), size, escape(fitted))]
        rows.append(Row(20, score_line))
        ack = run.acks.get(vname)
        if ack:
            rows.append(text_row("sensor: " + setting_text(ack), 12, "#444", 16, indent=10))
        rows.append(text_row("found %s, missed %s, false alarms %s" % (
            e.get("correct_hazards", "?"), e.get("missed_hazards", "?"),
            e.get("false_alarms", "?")), 12, "#444", 16, indent=10))
        rows.append(text_row("penalty %s (missed %s, FA %s, time %s)" % (
            e.get("total_score", "?"), e.get("score_missed_hazards", "?"),
            e.get("score_false_alarms", "?"), e.get("score_time_overage", "?")),
            12, "#444", 22, indent=10))
    return rows


SCORE_COLUMNS = [("vehicle", 0), ("score", 118), ("found", 178), ("missed", 228), ("FA", 284)]
SCORE_ROW_PX = 18


MAX_SETTING_ROWS = 3        # distinct sensor settings listed; more are counted in one line
MAX_NAMES_LISTED = 3        # a setting used by more vehicles names their count instead
MAX_HANDOVER_ROWS = 4       # hand-overs listed one per line; more are summed up in one line


def vehicle_swatch(x, y, col):
    """The vehicle's colour as a short bar on a dark plate: readable for any colour."""
    return ('<rect x="%.1f" y="%.1f" width="18" height="10" rx="2" fill="%s"/>'
            '<rect x="%.1f" y="%.1f" width="14" height="4" fill="%s"/>'
            % (x, y, MAP_BACKGROUND, x + 2, y + 3, col))


def setting_rows(run, vehicles):
    """One line per distinct sensor setting (UHZ_CONFIG_ACK) with the vehicles that used it."""
    settings = {}
    for vname in vehicles:
        ack = run.acks.get(vname)
        if ack:
            settings.setdefault(setting_text(ack), []).append(vname)
    if len(settings) > MAX_SETTING_ROWS:
        return [text_row("sensor: %d different settings" % len(settings), 12, "#444", 16)]
    rows = []
    for key, names in settings.items():
        if len(names) == len(vehicles) and len(names) > 1:
            who = "all"
        elif len(names) > MAX_NAMES_LISTED:
            who = "%d vehicles" % len(names)
        else:
            who = ", ".join(names)
        rows.append(text_row("sensor (%s): %s" % (who, key), 12, "#444", 16))
    return rows


def score_rows_compact(run, colour, vehicles_shown, hidden=0):
    """A table: one row per vehicle (name in its colour, score, found, missed, false alarms), a
    row for the `hidden` vehicles that did not fit, then one line per distinct sensor setting."""
    def header(y):
        return ['<text x="%d" y="%d" font-size="11" fill="#666">%s</text>'
                % (PANEL_X + dx, y + 11, name) for name, dx in SCORE_COLUMNS]
    rows = [Row(16, header)]
    for vname in vehicles_shown:
        e = run.evals[vname]

        def line(y, vname=vname, e=e):
            col = colour.get(vname, "#222")
            name, size = fit_text(vname, SCORE_COLUMNS[1][1] - 28, 14, 10, bold=True)
            parts = [vehicle_swatch(PANEL_X, y + 4, col),
                     '<text class="score" data-vehicle="%s" x="%d" y="%d" font-size="%g" '
                     'font-weight="bold" fill="%s"%s>%s</text>'
                     % (escape(vname), PANEL_X + 22, y + 13, size, col, name_outline(col),
                        escape(name))]
            cells = [e.get(k, "?") for k in
                     ("norm_score", "correct_hazards", "missed_hazards", "false_alarms")]
            edges = [dx for _name, dx in SCORE_COLUMNS[2:]] + [PANEL_W]
            for (label, dx), right, cell in zip(SCORE_COLUMNS[1:], edges, cells):
                bold = label == "score"
                fitted, cell_size = fit_text(cell, right - dx - 4, 13 if bold else 12, 9, bold)
                parts.append('<text x="%d" y="%d" font-size="%g" fill="#222"%s>%s</text>'
                             % (PANEL_X + dx, y + 13, cell_size,
                                ' font-weight="bold"' if bold else "", escape(fitted)))
            return parts
        rows.append(Row(SCORE_ROW_PX, line))
    if hidden:
        rows.append(text_row("+%d more vehicles (see summary.json)" % hidden, 12, "#444", 16))
    rows += setting_rows(run, sorted(run.evals))
    rows[-1].height += 6
    return rows


def summary_rows(run, final, objects, detail):
    hazards = sum(1 for o in objects if o["hazard"])
    rows = [text_row("truth: %d hazards, %d benign" % (hazards, len(objects) - hazards),
                     12, "#444", 18)]
    if len(run.handovers) <= MAX_HANDOVER_ROWS:
        for (source, dest, count) in run.handovers:
            rows.append(text_row("hand-over: %s gave %s %d objects" % (source, dest, count),
                                 12, "#444", 18, cls="handover"))
    else:
        rows.append(text_row("hand-overs: %d, %d objects in all" % (
            len(run.handovers), sum(c for _s, _d, c in run.handovers)), 12, "#444", 18,
            cls="handover"))
    if final:
        rows.append(text_row("last report: %s, %d objects" % (final[0], len(final[1])),
                             12, "#444", 18))
    if detail.field:
        rows.append(text_row("field view: {:,} objects, no labels (more than {:,})".format(
                             len(objects), DETAIL_MAX_OBJECTS)
                             if detail.auto else "field view: no labels",
                             12, "#444", 18, cls="detail-note"))
    return rows


def legend_symbol_poly(points, fill, stroke=None, opacity=1.0, width=1.5):
    return lambda cx, cy: ('<polygon points="%s" fill="%s" fill-opacity="%.2f" stroke="%s" '
                           'stroke-width="%.1f"/>' % (
                               " ".join("%.1f,%.1f" % (cx + px, cy - py) for px, py in points),
                               fill, opacity, stroke or fill, width))


def legend_symbol_ring(stroke, width, dash=False, radius=9):
    dash_attr = ' stroke-dasharray="4,2"' if dash else ""
    return lambda cx, cy: ('<circle cx="%.1f" cy="%.1f" r="%.1f" fill="none" stroke="%s" '
                           'stroke-width="%.1f"%s/>' % (cx, cy, radius, stroke, width, dash_attr))


def legend_symbol_dot(colour, diameter):
    return lambda cx, cy: ('<circle cx="%.1f" cy="%.1f" r="%.1f" fill="%s"/>'
                           % (cx, cy, diameter / 2, colour))


def legend_symbol_track(colour, width, swath_opacity=None):
    def draw(cx, cy):
        parts = []
        if swath_opacity is not None:
            parts.append('<rect x="%.1f" y="%.1f" width="20" height="12" fill="%s" opacity="%.2f"/>'
                         % (cx - 10, cy - 6, colour, swath_opacity))
        parts.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" '
                     'stroke-width="%.1f"/>' % (cx - 10, cy, cx + 10, cy, colour, width))
        return "".join(parts)
    return draw


def legend_entries(vehicles, colour, opts, detail, per_vehicle):
    """(symbol drawer taking the symbol's centre, text) for what this level of detail draws."""
    rows = []
    hazard_col = svg_colour(opts.hazard_color)
    benign_col = svg_colour(opts.benign_color)
    n = lambda key: "{:,}".format(detail.counts.get(key, 0))
    big = lambda px: min(px * FIELD_LEGEND_SYMBOL_SCALE, LEGEND_SYMBOL_MAX_PX)
    if detail.field:
        rows.append((legend_symbol_poly(marker_points(opts.hazard_shape, 0, 0,
                                                      big(detail.hazard_px)), hazard_col),
                     "hazard (ground truth): %s" % n("hazard")))
        rows.append((legend_symbol_poly(marker_points(opts.benign_shape, 0, 0,
                                                      big(detail.benign_px)), benign_col,
                                        opacity=0.5),
                     "benign object (fill 1 - hr): %s" % n("benign")))
    else:
        rows.append((legend_symbol_poly(marker_points(opts.hazard_shape, 0, 0, 14), hazard_col),
                     "hazard (ground truth)"))
        rows.append((legend_symbol_poly(marker_points(opts.benign_shape, 0, 0, 14), benign_col,
                                        opacity=0.5), "benign object (fill 1 - hr)"))
    rows.append((lambda cx, cy: '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#b0b0b0" '
                 'stroke-width="2" stroke-dasharray="8,5"/>' % (cx - 10, cy, cx + 10, cy),
                 "search region"))
    if per_vehicle:
        for v in vehicles:
            rows.append((legend_symbol_track(colour[v], 3), "%s track" % v))
            rows.append((lambda cx, cy, c=colour[v]: '<rect x="%.1f" y="%.1f" width="20" '
                         'height="12" fill="%s" opacity="%.2f"/>'
                         % (cx - 10, cy - 6, c, SWATH_OPACITY + 0.2),
                         "%s swath coverage (sensor on)" % v))
    elif vehicles:
        sample = colour[vehicles[0]]
        rows.append((legend_symbol_track(sample, detail.track_width_px + 1,
                                         detail.swath_opacity + 0.2),
                     "track, swath coverage (colour above)"))
    if detail.field:
        texts = {"detection": "detected, not classified: %s",
                 "classification hazard": "classified hazard (last answer): %s",
                 "classification benign": "classified benign (last answer): %s",
                 "pink": "last cue changed by aspect: %s"}
        dot_colour = dict(CUE_DOTS)
        for cls in ("detection", "classification hazard", "classification benign", "pink"):
            rows.append((legend_symbol_dot(dot_colour[cls], min(
                detail.dot_px * FIELD_LEGEND_DOT_SCALE, LEGEND_DOT_MAX_PX)),
                         texts[cls] % n(cls)))
        rows.append((legend_symbol_ring("#ff3030", 1.8, radius=big(detail.ring_px) / 2),
                     "hazard missed by the last report: %s" % n("missed")))
    else:
        rows.append((legend_symbol_poly(regular_polygon(0, 0, 9, 12), "white", opacity=0.3),
                     "detection"))
        rows.append((legend_symbol_poly(regular_polygon(0, 0, 9, 12), "pink", opacity=0.5),
                     "detection changed by aspect"))
        rows.append((legend_symbol_poly(regular_polygon(0, 0, 9, 5), "yellow", opacity=0.3),
                     "classified hazard"))
        rows.append((legend_symbol_poly(regular_polygon(0, 0, 9, 5), "green", opacity=0.3),
                     "classified benign"))
        rows.append((legend_symbol_poly(regular_polygon(0, 0, 9, 5), "pink", stroke="yellow",
                                        opacity=0.5, width=3), "classification changed by aspect"))
        rows.append((legend_symbol_ring("#ffffff", 2, dash=True), "in the last HAZARDSET_REPORT"))
        rows.append((legend_symbol_ring("#ff3030", 3), "hazard missed by that report"))
    return rows


def legend_rows(entries, row_px):
    """The legend as panel rows: a heading, then one row per entry on a dark plate."""
    plate_pad = 4

    def heading(y):
        return ['<text x="%d" y="%d" font-size="18" font-weight="bold" fill="#222">Legend</text>'
                % (PANEL_X, y + 16),
                '<rect class="legend-plate" x="%d" y="%d" width="%d" height="%d" fill="%s" rx="4"/>'
                % (PANEL_X - 6, y + 28 - plate_pad, PANEL_W + 6, row_px * len(entries) + 8,
                   MAP_BACKGROUND)]
    rows = [Row(28, heading)]
    font_px = min(13.0, row_px - 6)
    for draw, text in entries:
        def line(y, draw=draw, text=text):
            return [draw(PANEL_X + 14, y + row_px / 2 - 2),
                    svg_text(PANEL_X + 34, y + row_px / 2 + font_px / 2 - 1, text, font_px,
                             "#f0f0f0", PANEL_W - 34 - 4, extra=' class="legend-entry"')]
        rows.append(Row(row_px, line))
    rows[-1].height += 8
    return rows


LEGEND_ROW_PX = (24, 20, 17)   # legend row heights tried in turn; the font is 6 px less, 13 at most


def unscored_rows(vehicles, colour, run):
    """Vehicles with a track but no score still need their colour explained: three a row."""
    unscored = [v for v in vehicles if v not in run.evals]
    per_row, column_px = 3, PANEL_W // 3
    rows = []
    for start in range(0, min(len(unscored), 2 * per_row), per_row):
        def line(y, names=unscored[start:start + per_row]):
            return [vehicle_swatch(PANEL_X + column_px * i, y + 4, colour[v]) +
                    svg_text(PANEL_X + column_px * i + 22, y + 13, v, 12, colour[v],
                             column_px - 26, bold=True, extra=name_outline(colour[v]))
                    for i, v in enumerate(names)]
        rows.append(Row(18, line))
    if len(unscored) > 2 * per_row:
        rows.append(text_row("+%d more tracked vehicles" % (len(unscored) - 2 * per_row),
                             12, "#444", 16))
    return rows


def panel_layouts(run, final, objects, vehicles, colour, opts, detail):
    """Panel layouts from the most to the least detailed; the first one that fits is drawn.

    The full score block and per-vehicle legend rows (the Jake picture) come first; then the
    legend folds the vehicles into one row (the score names them in their colours); then the
    score becomes a table of one row per vehicle; then the legend rows tighten; last, the table
    shows as many vehicles as fit and counts the others."""
    scored = sorted(run.evals)
    score = [heading_row("Score")]
    if not scored:
        score.append(text_row("no HAZARDSET_EVAL in the log", 13, "#666", 24))
    summary = summary_rows(run, final, objects, detail)
    unscored = unscored_rows(vehicles, colour, run)
    gap = [Row(20, lambda y: [])]
    per_vehicle = legend_entries(vehicles, colour, opts, detail, True)
    folded = legend_entries(vehicles, colour, opts, detail, False)
    full = score + score_rows_full(run, colour, scored)
    yield full + summary + gap + legend_rows(per_vehicle, LEGEND_ROW_PX[0])
    yield full + unscored + summary + gap + legend_rows(folded, LEGEND_ROW_PX[0])
    for row_px in LEGEND_ROW_PX:
        table = score_rows_compact(run, colour, scored) if scored else []
        yield score + table + unscored + summary + gap + legend_rows(folded, row_px)
    rest = unscored + summary + gap + legend_rows(folded, LEGEND_ROW_PX[-1])
    for shown in range(len(scored) - 1, 0, -1):
        table = score_rows_compact(run, colour, scored[:shown], len(scored) - shown)
        if panel_height(score + table + rest) <= PANEL_BOTTOM - MAP_Y:
            break
    else:
        table = [text_row("%d vehicles scored (see summary.json)" % len(scored), 12, "#444", 18)]
    yield score + table + rest


def panel_height(rows):
    return sum(r.height for r in rows)


def draw_panel(w, run, final, objects, vehicles, colour, opts, detail):
    chosen = None
    for rows in panel_layouts(run, final, objects, vehicles, colour, opts, detail):
        chosen = rows
        if panel_height(rows) <= PANEL_BOTTOM - MAP_Y:
            break
    y = MAP_Y
    w('<g class="panel">')
    for row in chosen:
        if y + row.height > PANEL_BOTTOM + 8:   # a row that cannot fit is left out, never drawn
            break                               # outside the frame (the +8: trailing spacing)
        for part in row.draw(y):
            w(part)
        y += row.height
    w('</g>')


# ---------------------------------------------------------------------------------------------

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
        read_alog(opts.alog, run)
    objects, region = read_hazard_file(opts.hazards) if opts.hazards else ([], None)
    summary = read_summary(opts.summary, run) if opts.summary else None
    if summary and not opts.title and isinstance(summary.get("title"), str):
        opts.title = summary["title"]

    svg = render(run, objects, region, opts)
    try:
        with open(opts.svg, "w", encoding="utf-8") as f:
            f.write(svg)
    except OSError as e:
        warn("cannot write %s: %s" % (opts.svg, e))
        return 1
    if opts.no_png:
        return 0
    png = opts.png or os.path.splitext(opts.svg)[0] + ".png"
    converter = shutil.which("rsvg-convert")
    if not converter:
        warn("rsvg-convert not found (Debian package librsvg2-bin): no PNG written")
        return 0
    command = [converter, "-w", str(CANVAS_W), "-h", str(CANVAS_H), "-o", png, opts.svg]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    if result.returncode != 0:
        warn("rsvg-convert failed: %s" % result.stderr.decode(errors="replace").strip())
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
