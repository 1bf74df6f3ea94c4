#!/usr/bin/env python3
"""Render a finished hazard-search run as a picture (SVG, and PNG through rsvg-convert).

Usage:
  render_mission.py --alog RUN.alog --hazards hazards.txt [--summary summary.json]
                    [--svg OUT.svg] [--png OUT.png] [--title TEXT]
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
    UHZ_DETECTION_REPORT / UHZ_HAZARD_REPORT with the D19 colours;
  - the last HAZARDSET_REPORT: dashed rings around the reported objects, red rings around hazards
    it missed;
  - the score table from HAZARDSET_EVAL in the log (latest per vehicle), else from summary.json;
  - a scale bar and a north arrow.

Input problems never stop the picture: malformed lines and values are reported on stderr with their
line number and skipped. Python 3 standard library only.
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
from xml.sax.saxutils import escape

# ---------------------------------------------------------------------------------------------
# Layout and style constants (pixels unless stated).

CANVAS_W, CANVAS_H = 1200, 900
MAP_X, MAP_Y, MAP_W, MAP_H = 20, 60, 820, 820      # the map viewport
PANEL_X = MAP_X + MAP_W + 20                        # the right-hand panel (legend, scores)
MAP_BACKGROUND = "#1b2736"                          # dark, like a viewer: white cues stay visible
VEHICLE_COLOURS = ["#ff8c42", "#e040fb", "#26c6da", "#c0ca33", "#ff5252", "#ffffff"]
SWATH_OPACITY = 0.18
DETECTION_RADIUS_M = 10.0                           # D19 / spec 5.3
DEFAULT_MARKER_WIDTH_M = 8.0                        # manual 7.6
REPORT_RING_M = 15.0                                # drawn outside the radius-10 cues
MIN_TRACK_STEP_M = 0.5                              # track thinning
SWATH_STEP_M = 2.0                                  # swath rectangles kept at least this far apart
SENSOR_MAX_TURN_RATE_DPS = 1.5                      # manual 8
SENSOR_MAX_SPEED_MPS = 2.0                          # rulings D14
SWATH_LENGTH_M = 5.0                                # rulings D1 (total, along track)
TURN_WINDOW_S = 2.0                                 # spec 8.2

warnings_count = 0


def warn(message):
    global warnings_count
    warnings_count += 1
    print("render_mission: " + message, file=sys.stderr)


# ---------------------------------------------------------------------------------------------
# MOOS text helpers.

def split_outside_braces(text, sep=","):
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c == "{":
            depth += 1
        elif c == "}" and depth > 0:
            depth -= 1
        elif c == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def key_values(text):
    """`a=1,b=2` -> {'a': '1', 'b': '2'} with lower-case keys; braces respected."""
    out = {}
    for piece in split_outside_braces(text):
        if "=" in piece:
            k, v = piece.split("=", 1)
            out[k.strip().lower()] = v.strip()
    return out


NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def number(text):
    if text is None:
        return None
    text = text.strip()
    if not NUMBER.match(text):
        return None
    v = float(text)
    return v if math.isfinite(v) else None


def parse_points(text):
    """`pts={x1,y1:x2,y2}` or `x1,y1:x2,y2` -> [(x, y), ...] or None."""
    m = re.search(r"pts\s*=\s*\{([^}]*)\}", text)
    body = m.group(1) if m else text
    points = []
    for vertex in body.split(":"):
        coords = vertex.split(",")
        if len(coords) < 2:
            return None
        x, y = number(coords[0]), number(coords[1])
        if x is None or y is None:
            return None
        points.append((x, y))
    return points if points else None


CSS_NAMES = {"lightblue", "green", "yellow", "white", "pink", "red", "blue", "orange", "black",
             "gray", "grey", "darkgreen", "lightgreen", "cyan", "magenta", "purple", "brown",
             "gold", "navy", "violet", "khaki", "salmon", "tan", "teal", "olive", "silver",
             "darkblue", "lightgray", "lightgrey", "darkgray", "darkgrey", "hotpink", "coral",
             "crimson", "turquoise", "lime", "maroon", "beige", "ivory", "orchid", "plum"}


def svg_colour(moos, fallback="#999999"):
    """A MOOS colour word (manual colour appendix) as an SVG colour."""
    if not moos:
        return fallback
    word = moos.strip().lower().replace("_", "")
    m = re.match(r"^gr[ae]y(\d{1,3})$", word)
    if m and int(m.group(1)) <= 100:
        level = round(int(m.group(1)) * 255 / 100)
        return "#%02x%02x%02x" % (level, level, level)
    m = re.match(r"^hex:([0-9a-f]{2}),([0-9a-f]{2}),([0-9a-f]{2})$", word)
    if m:
        return "#" + "".join(m.groups())
    if word in ("invisible", "empty"):
        return "none"
    if re.match(r"^[a-z]+$", word):
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
        self.detections = []      # (vehicle, label, x, y)
        self.classifications = [] # (vehicle, label, x, y, type)
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


def read_alog(path, run):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
    except OSError as e:
        warn("cannot read log %s: %s" % (path, e))
        return
    for n, raw in enumerate(lines, 1):
        line = raw.rstrip("\r")
        if not line.strip():
            continue
        if line.lstrip().startswith("%%"):
            m = re.match(r"\s*%%\s*LOG FILE:\s*(\S+)", line)
            if m:
                run.log_name = m.group(1)
            continue
        parts = line.split(None, 3)
        t = number(parts[0]) if parts else None
        if t is None or len(parts) < 3:
            warn("%s:%d: malformed line skipped (expected TIME VARIABLE SOURCE VALUE)" % (path, n))
            continue
        value = parts[3] if len(parts) > 3 else ""
        try:
            handle(run, t, parts[1], value, "%s:%d" % (path, n))
        except Exception as e:  # one bad value never stops the picture
            warn("%s:%d: %s value skipped (%s)" % (path, n, parts[1], e))


def handle(run, t, var, value, place):
    if var in ("NODE_REPORT", "NODE_REPORT_LOCAL"):
        kv = {k.upper(): v for k, v in key_values(value).items()}
        name = kv.get("NAME")
        x, y = number(kv.get("X")), number(kv.get("Y"))
        hdg = number(kv.get("HDG", kv.get("HEADING")))
        spd = number(kv.get("SPD", kv.get("SPEED")))
        if not name or x is None or y is None:
            warn("%s: NODE_REPORT without NAME, X and Y skipped" % place)
            return
        track = run.tracks.setdefault(name, [])
        if not track or track[-1][:3] != (t, x, y):
            track.append((t, x, y, hdg if hdg is not None else 0.0,
                          spd if spd is not None else 0.0))
    elif var == "VIEW_POLYGON":
        kv = key_values(value)
        label = kv.get("label", "")
        pts = parse_points(value)
        if pts is None:
            warn("%s: VIEW_POLYGON without points skipped" % place)
        elif label.startswith("sensor_swath_") and len(pts) == 4:
            on = kv.get("fill_color", "white").lower() != "red"
            run.swaths.setdefault(label[len("sensor_swath_"):], []).append((t, pts, on))
        elif label == "search_region" and run.region is None:
            run.region = pts
    elif var.startswith("UHZ_CONFIG_ACK"):
        kv = key_values(value)
        w = number(kv.get("width"))
        if kv.get("vname") and w is not None:
            run.widths[kv["vname"]] = w
            run.acks[kv["vname"]] = kv
    elif var == "HAZARD_HANDOVER":
        parts = [p.strip() for p in value.split("#")]
        header = {}
        for p in parts[:3]:
            header.update(key_values(p))
        if header.get("source") and header.get("dest"):
            run.handovers.append((header["source"], header["dest"], max(0, len(parts) - 3)))
        else:
            warn("%s: HAZARD_HANDOVER without source and dest skipped" % place)
    elif var == "VIEW_CIRCLE":
        kv = key_values(value)
        x, y = number(kv.get("x")), number(kv.get("y"))
        if x is None or y is None:
            warn("%s: VIEW_CIRCLE without x and y skipped" % place)
            return
        run.circles.append({"x": x, "y": y,
                            "radius": number(kv.get("radius")) or DETECTION_RADIUS_M,
                            "vertices": int(number(kv.get("vertices")) or 12),
                            "edge": kv.get("edge_color"), "fill": kv.get("fill_color"),
                            "edge_size": number(kv.get("edge_size")) or 1.0,
                            "transparency": number(kv.get("fill_transparency"))})
    elif var == "UHZ_DETECTION_REPORT":
        kv = key_values(value)
        x, y = number(kv.get("x")), number(kv.get("y"))
        if x is not None and y is not None:
            run.detections.append((kv.get("vname", ""), kv.get("label", ""), x, y))
    elif var == "UHZ_HAZARD_REPORT":
        kv = key_values(value)
        x, y = number(kv.get("x")), number(kv.get("y"))
        if x is not None and y is not None:
            run.classifications.append((kv.get("vname", ""), kv.get("label", ""), x, y,
                                        kv.get("type", "")))
    elif var == "VIEW_MARKER":
        kv = key_values(value)
        if kv.get("label"):
            run.markers[kv["label"]] = kv
    elif var == "UHZ_MISSION_PARAMS":
        kv = key_values(value)
        if run.region is None and "search_region" in kv:
            run.region = parse_points(kv["search_region"])
    elif var == "HAZARDSET_REPORT":
        source, labels = "", []
        for part in value.split("#"):
            part = part.strip()
            if part.startswith("source"):
                source = part.split("=", 1)[-1].strip()
            elif part.startswith(("name", "transit_path_width", "search_region")):
                continue
            else:
                label = key_values(part).get("label")
                if label:
                    labels.append(label)
        if source:
            run.reports.append((source, labels))
        else:
            warn("%s: HAZARDSET_REPORT without source skipped" % place)
    elif var == "HAZARDSET_EVAL":
        kv = key_values(value)
        if kv.get("vname"):
            run.evals[kv["vname"]] = kv
        else:
            warn("%s: HAZARDSET_EVAL without vname skipped" % place)


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
    """Per track sample: was the sensor on (spec 8.2 turn rate over 2 s, speed limit)?"""
    flags, window = [], []
    for (t, _x, _y, hdg, spd) in track:
        window.append((t, hdg))
        while window and t - window[0][0] >= TURN_WINDOW_S:
            window.pop(0)
        total = sum(abs((b[1] - a[1] + 180.0) % 360.0 - 180.0) for a, b in zip(window, window[1:]))
        span = window[-1][0] - window[0][0]
        rate = total / span if span > 0 else 0.0
        flags.append(rate <= SENSOR_MAX_TURN_RATE_DPS and spd <= SENSOR_MAX_SPEED_MPS)
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


# ---------------------------------------------------------------------------------------------
# Drawing.

def render(run, objects, hazard_region, opts):
    out = []
    w = out.append
    region = hazard_region or run.region
    vehicles = sorted(set(run.tracks) | set(run.swaths))
    colour = {v: VEHICLE_COLOURS[i % len(VEHICLE_COLOURS)] for i, v in enumerate(vehicles)}

    extent = [(o["x"], o["y"]) for o in objects] + list(region or [])
    for track in run.tracks.values():
        extent += [(p[1], p[2]) for p in track]
    view = View(extent)

    w('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" '
      'font-family="DejaVu Sans, Arial, sans-serif">' % (CANVAS_W, CANVAS_H, CANVAS_W, CANVAS_H))
    w('<rect x="0" y="0" width="%d" height="%d" fill="#f4f4f0"/>' % (CANVAS_W, CANVAS_H))
    title = opts.title or ("Hazard search: " + (run.log_name or os.path.basename(opts.alog or "")))
    w('<text x="%d" y="38" font-size="24" font-weight="bold" fill="#222">%s</text>'
      % (MAP_X, escape(title)))
    w('<clipPath id="map"><rect x="%d" y="%d" width="%d" height="%d"/></clipPath>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H))
    w('<rect class="map" x="%d" y="%d" width="%d" height="%d" fill="%s"/>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H, MAP_BACKGROUND))
    w('<g clip-path="url(#map)">')

    if region:
        w('<polygon class="region" points="%s" fill="#24364a" stroke="#b0b0b0" stroke-width="2" '
          'stroke-dasharray="8,5"/>' % view.pts(region))

    # Swath coverage: opaque shapes in a translucent group, so overlaps do not darken.
    for v in vehicles:
        w('<g class="swath" data-vehicle="%s" opacity="%.2f" fill="%s" stroke="none">'
          % (escape(v), SWATH_OPACITY, colour[v]))
        if run.swaths.get(v):
            last = None
            for (_t, pts, on) in run.swaths[v]:
                cx = sum(p[0] for p in pts) / 4
                cy = sum(p[1] for p in pts) / 4
                if not on or (last and math.hypot(cx - last[0], cy - last[1]) < SWATH_STEP_M):
                    continue
                last = (cx, cy)
                w('<polygon points="%s"/>' % view.pts(pts))
        elif run.tracks.get(v) and run.widths.get(v):
            track = run.tracks[v]
            width_px = 2 * run.widths[v] * view.scale
            segment = []
            for p, on in zip(track, turn_rate_flags(track)):
                if on:
                    segment.append((p[1], p[2]))
                elif segment:
                    if len(segment) > 1:
                        w('<polyline points="%s" fill="none" stroke="%s" stroke-width="%.1f" '
                          'stroke-linecap="butt"/>' % (view.pts(segment), colour[v], width_px))
                    segment = []
            if len(segment) > 1:
                w('<polyline points="%s" fill="none" stroke="%s" stroke-width="%.1f" '
                  'stroke-linecap="butt"/>' % (view.pts(segment), colour[v], width_px))
        w('</g>')

    # Tracks.
    for v in vehicles:
        track = run.tracks.get(v, [])
        kept, last = [], None
        for p in track:
            if last is None or math.hypot(p[1] - last[0], p[2] - last[1]) >= MIN_TRACK_STEP_M:
                kept.append((p[1], p[2]))
                last = (p[1], p[2])
        if len(kept) > 1:
            w('<polyline class="track" data-vehicle="%s" points="%s" fill="none" stroke="%s" '
              'stroke-width="2" stroke-linejoin="round"/>' % (escape(v), view.pts(kept), colour[v]))
        if kept:
            x, y = view.px(*kept[-1])
            w('<circle class="vehicle-end" cx="%.1f" cy="%.1f" r="5" fill="%s" stroke="#000"/>'
              % (x, y, colour[v]))
            right = x > MAP_X + MAP_W - 80  # keep the name inside the map
            w('<text x="%.1f" y="%.1f" font-size="14" font-weight="bold" fill="%s"%s>%s</text>'
              % (x - 8 if right else x + 8, y - 8, colour[v],
                 ' text-anchor="end"' if right else "", escape(v)))

    # Objects.
    for o in objects:
        style = run.markers.get(o["label"], {})
        hazard = o["hazard"]
        shape = (style.get("type") or o["shape"] or
                 (opts.hazard_shape if hazard else opts.benign_shape)).lower()
        col = svg_colour(style.get("primary_color") or o["color"] or
                         (opts.hazard_color if hazard else opts.benign_color))
        width = number(style.get("width")) or o["width"] or DEFAULT_MARKER_WIDTH_M
        width = max(width * view.scale, 7.0) / view.scale  # at least 7 px: always visible
        opacity = 1.0
        if not hazard:
            # Spec 5.4: a benign marker's fill_transparency (the viewer's alpha) is 1 - hr, 0.5
            # without hr. The edge is always drawn, so a fully clear fill still shows the shape.
            alpha = number(style.get("fill_transparency"))
            if alpha is None:
                alpha = 1.0 - (o["hr"] if o["hr"] is not None else 0.5)
            opacity = min(1.0, max(0.0, alpha))
        w('<polygon class="marker %s" data-label="%s" points="%s" fill="%s" fill-opacity="%.2f" '
          'stroke="%s" stroke-width="1.5"/>'
          % ("hazard" if hazard else "benign", escape(o["label"]),
             view.pts(marker_points(shape, o["x"], o["y"], width)), col, opacity, col))
        lx, ly = view.px(o["x"], o["y"])
        offset = DETECTION_RADIUS_M * view.scale * 0.75 + 3  # beside the radius-10 cues
        w('<text class="label" x="%.1f" y="%.1f" font-size="11" fill="#e0e0e0">%s</text>'
          % (lx + offset, ly + offset + 8, escape(o["label"])))

    # Detections and classifications.
    circles = run.circles or derived_circles(run)
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

    # The final report: dashed rings on the reported objects, red rings on missed hazards.
    final = run.reports[-1] if run.reports else None
    if final:
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

    draw_scale_and_north(w, view)
    w('</g>')
    w('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#555" stroke-width="1"/>'
      % (MAP_X, MAP_Y, MAP_W, MAP_H))
    if not objects and not run.tracks:
        w('<text x="%d" y="%d" font-size="20" fill="#dddddd" text-anchor="middle">'
          'no objects and no tracks in the inputs</text>' % (MAP_X + MAP_W / 2, MAP_Y + MAP_H / 2))

    y = draw_scores(w, run, final, objects, colour)
    draw_legend(w, run, vehicles, colour, opts, y + 20)
    w('</svg>')
    return "\n".join(out) + "\n"


def derived_circles(run):
    """D19 cues rebuilt from the reports when the log has no VIEW_CIRCLE postings."""
    circles = [{"x": x, "y": y, "radius": DETECTION_RADIUS_M, "vertices": 12, "edge": "white",
                "fill": "white", "edge_size": 1.0, "transparency": 0.7}
               for (_v, _l, x, y) in run.detections]
    for (_v, _l, x, y, typ) in run.classifications:
        colour = "yellow" if typ == "hazard" else "green"
        circles.append({"x": x, "y": y, "radius": DETECTION_RADIUS_M, "vertices": 5, "edge": colour,
                        "fill": colour, "edge_size": 1.0, "transparency": 0.7})
    return circles


def draw_scale_and_north(w, view):
    length_m = nice_length(MAP_W * 0.25 / view.scale)
    length_px = length_m * view.scale
    x0, y0 = MAP_X + 20, MAP_Y + MAP_H - 25
    w('<g class="scale-bar">')
    w('<rect x="%.1f" y="%.1f" width="%.1f" height="8" fill="#ffffff"/>' % (x0, y0, length_px / 2))
    w('<rect x="%.1f" y="%.1f" width="%.1f" height="8" fill="none" stroke="#ffffff"/>'
      % (x0, y0, length_px))
    label = ("%g m" % length_m) if length_m < 1000 else ("%g km" % (length_m / 1000))
    w('<text x="%.1f" y="%.1f" font-size="14" fill="#ffffff">0</text>' % (x0 - 4, y0 - 6))
    w('<text x="%.1f" y="%.1f" font-size="14" fill="#ffffff" text-anchor="middle">%s</text>'
      % (x0 + length_px, y0 - 6, label))
    w('</g>')
    nx, ny = MAP_X + MAP_W - 40, MAP_Y + 30
    w('<g class="north-arrow">')
    w('<polygon points="%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f" fill="#ffffff" stroke="#000"/>'
      % (nx, ny - 20, nx + 11, ny + 14, nx, ny + 6, nx - 11, ny + 14))
    w('<text x="%.1f" y="%.1f" font-size="16" font-weight="bold" fill="#ffffff" '
      'text-anchor="middle">N</text>' % (nx, ny + 34))
    w('</g>')


def draw_scores(w, run, final, objects, colour):
    x, y = PANEL_X, MAP_Y
    w('<g class="score-table">')
    w('<text x="%d" y="%d" font-size="18" font-weight="bold" fill="#222">Score</text>'
      % (x, y + 16))
    y += 30
    if not run.evals:
        w('<text x="%d" y="%d" font-size="13" fill="#666">no HAZARDSET_EVAL in the log</text>'
          % (x, y + 12))
        y += 24
    for vname in sorted(run.evals):
        e = run.evals[vname]
        w('<text class="score" data-vehicle="%s" x="%d" y="%d" font-size="15" fill="#222">'
          '<tspan font-weight="bold" fill="%s" stroke="#444" stroke-width="0.3">%s</tspan>: '
          '%s / 100</text>'
          % (escape(vname), x, y + 14, colour.get(vname, "#222"), escape(vname),
             escape(e.get("norm_score", "?"))))
        y += 20
        ack = run.acks.get(vname)
        if ack:
            w('<text x="%d" y="%d" font-size="12" fill="#444">sensor: swath %s m, pd %s, pfa %s, '
              'pclass %s</text>' % (x + 10, y + 12, escape(ack.get("width", "?")),
                                    escape(ack.get("pd", "?")), escape(ack.get("pfa", "?")),
                                    escape(ack.get("pclass", "?"))))
            y += 16
        details = "found %s, missed %s, false alarms %s" % (
            e.get("correct_hazards", "?"), e.get("missed_hazards", "?"), e.get("false_alarms", "?"))
        w('<text x="%d" y="%d" font-size="12" fill="#444">%s</text>' % (x + 10, y + 12, details))
        y += 16
        w('<text x="%d" y="%d" font-size="12" fill="#444">penalty %s (missed %s, FA %s, time %s)'
          '</text>' % (x + 10, y + 12, e.get("total_score", "?"),
                       e.get("score_missed_hazards", "?"), e.get("score_false_alarms", "?"),
                       e.get("score_time_overage", "?")))
        y += 22
    hazards = sum(1 for o in objects if o["hazard"])
    w('<text x="%d" y="%d" font-size="12" fill="#444">truth: %d hazards, %d benign</text>'
      % (x, y + 12, hazards, len(objects) - hazards))
    y += 18
    for (source, dest, count) in run.handovers:
        w('<text class="handover" x="%d" y="%d" font-size="12" fill="#444">hand-over: %s gave %s '
          '%d objects</text>' % (x, y + 12, escape(source), escape(dest), count))
        y += 18
    if final:
        w('<text x="%d" y="%d" font-size="12" fill="#444">last report: %s, %d objects</text>'
          % (x, y + 12, escape(final[0]), len(final[1])))
        y += 18
    w('</g>')
    return y


def draw_legend(w, run, vehicles, colour, opts, y):
    x = PANEL_X
    rows = []  # (symbol drawer taking the symbol's centre, text)

    def poly(points, fill, stroke=None, opacity=1.0, width=1.5, dash=None):
        def draw(cx, cy):
            return ('<polygon points="%s" fill="%s" fill-opacity="%.2f" stroke="%s" '
                    'stroke-width="%.1f"%s/>' % (
                        " ".join("%.1f,%.1f" % (cx + px, cy - py) for px, py in points), fill,
                        opacity, stroke or fill, width,
                        ' stroke-dasharray="%s"' % dash if dash else ""))
        return draw

    def ring(stroke, width, dash=None):
        dash_attr = ' stroke-dasharray="4,2"' if dash else ""
        return lambda cx, cy: ('<circle cx="%.1f" cy="%.1f" r="9" fill="none" stroke="%s" '
                               'stroke-width="%d"%s/>' % (cx, cy, stroke, width, dash_attr))

    hazard_col = svg_colour(opts.hazard_color)
    benign_col = svg_colour(opts.benign_color)
    rows.append((poly(marker_points(opts.hazard_shape, 0, 0, 14), hazard_col),
                 "hazard (ground truth)"))
    rows.append((poly(marker_points(opts.benign_shape, 0, 0, 14), benign_col, opacity=0.5),
                 "benign object (fill 1 - hr)"))
    rows.append((lambda cx, cy: '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#b0b0b0" '
                 'stroke-width="2" stroke-dasharray="8,5"/>' % (cx - 10, cy, cx + 10, cy),
                 "search region"))
    for v in vehicles:
        rows.append((lambda cx, cy, c=colour[v]: '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" '
                     'stroke="%s" stroke-width="3"/>' % (cx - 10, cy, cx + 10, cy, c),
                     "%s track" % v))
        rows.append((lambda cx, cy, c=colour[v]: '<rect x="%.1f" y="%.1f" width="20" height="12" '
                     'fill="%s" opacity="%.2f"/>' % (cx - 10, cy - 6, c, SWATH_OPACITY + 0.2),
                     "%s swath coverage (sensor on)" % v))
    rows.append((poly(regular_polygon(0, 0, 9, 12), "white", opacity=0.3), "detection"))
    rows.append((poly(regular_polygon(0, 0, 9, 12), "pink", opacity=0.5),
                 "detection changed by aspect"))
    rows.append((poly(regular_polygon(0, 0, 9, 5), "yellow", opacity=0.3), "classified hazard"))
    rows.append((poly(regular_polygon(0, 0, 9, 5), "green", opacity=0.3), "classified benign"))
    rows.append((poly(regular_polygon(0, 0, 9, 5), "pink", stroke="yellow", opacity=0.5, width=3),
                 "classification changed by aspect"))
    rows.append((ring("#ffffff", 2, dash=True), "in the last HAZARDSET_REPORT"))
    rows.append((ring("#ff3030", 3), "hazard missed by that report"))

    w('<g class="legend">')
    w('<text x="%d" y="%d" font-size="18" font-weight="bold" fill="#222">Legend</text>'
      % (x, y + 16))
    y += 28
    w('<rect x="%d" y="%d" width="330" height="%d" fill="%s" rx="4"/>'
      % (x - 6, y - 4, 24 * len(rows) + 8, MAP_BACKGROUND))
    for draw, text in rows:
        w(draw(x + 14, y + 10))
        w('<text x="%d" y="%d" font-size="13" fill="#f0f0f0">%s</text>'
          % (x + 34, y + 15, escape(text)))
        y += 24
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
