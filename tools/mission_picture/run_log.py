"""The run as the picture needs it: the drawn variables of the .alog, the hazard file and
summary.json, read through tools/mission_files. Input problems are warnings on stderr
with their place, never a stop."""

import re
import sys

from mission_files.alog import AlogHeader, AlogSkips, read_alog
from mission_files.hazard_file import read_hazard_file
from mission_files.messages import hazard_handover, hazardset_report
from mission_files.run_files import read_summary, summary_evals
from mission_files.text import key_values, parse_number, parse_points

from .layout import DETECTION_RADIUS_M


def warn(message):
    print("render_mission: " + message, file=sys.stderr)


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
    x, y = parse_number(x), parse_number(y)
    if not name or x is None or y is None:
        warn("%s: NODE_REPORT without NAME, X and Y skipped" % where(place))
        return
    hdg, spd = parse_number(hdg), parse_number(spd)
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
    w = parse_number(kv.get("width"))
    if kv.get("vname") and w is not None:
        run.widths[kv["vname"]] = w
        run.acks[kv["vname"]] = kv


def on_handover(run, t, value, place):
    header, objects = hazard_handover(value)
    if header.get("source") and header.get("dest"):
        run.handovers.append((header["source"], header["dest"], objects))
    else:
        warn("%s: HAZARD_HANDOVER without source and dest skipped" % where(place))


def on_view_circle(run, t, value, place):
    kv = key_values(value)
    x, y = parse_number(kv.get("x")), parse_number(kv.get("y"))
    if x is None or y is None:
        warn("%s: VIEW_CIRCLE without x and y skipped" % where(place))
        return
    run.circles.append({"x": x, "y": y,
                        "radius": parse_number(kv.get("radius")) or DETECTION_RADIUS_M,
                        "vertices": int(parse_number(kv.get("vertices")) or 12),
                        "edge": kv.get("edge_color"), "fill": kv.get("fill_color"),
                        "edge_size": parse_number(kv.get("edge_size")) or 1.0,
                        "transparency": parse_number(kv.get("fill_transparency"))})


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
    source, labels = hazardset_report(value)
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


# The variables read: a pattern's C-level match, as it runs once per log line.
WANTED = re.compile("|".join(re.escape(v) for v in HANDLERS) + "|" + CONFIG_ACK_PREFIX + ".*")


def read_log(path, run):
    """Stream the log once; only the variables drawn are parsed (mission_files.alog)."""
    header = AlogHeader()
    skips = AlogSkips()
    try:
        entries = read_alog(path, WANTED.fullmatch, lambda n, _why: warn_malformed(path, n), header,
                            skips)
    except OSError as e:
        warn("cannot read log %s: %s" % (path, e))
        return
    for t, var, _source, value, n in entries:
        handler = HANDLERS.get(var, on_config_ack)
        place = (path, n)   # formatted only for a warning
        try:
            handler(run, t, value, place)
        except Exception as e:  # one bad value never stops the picture
            warn("%s: %s value skipped (%s)" % (where(place), var, e))
    for message in skips.warnings(path):   # one line per kind, with the count
        warn(message)
    run.log_name = header.log_name


def read_hazards(path):
    """(objects, region) of the hazard file; its problems are warnings, an unreadable file gives
    no objects."""
    try:
        hazards = read_hazard_file(path)
    except OSError as e:
        warn("cannot read hazard file %s: %s" % (path, e))
        return [], None
    for message in hazards.warnings:
        warn(message)
    return hazards.objects, hazards.region


def report_positions(values, with_type):
    """UHZ_DETECTION_REPORT / UHZ_HAZARD_REPORT values -> [(x, y, type)]; bad ones named."""
    out = []
    for value, place in values:
        kv = key_values(value)
        x, y = parse_number(kv.get("x")), parse_number(kv.get("y"))
        if x is None or y is None:
            warn("%s: report without x and y skipped" % where(place))
            continue
        out.append((x, y, kv.get("type", "") if with_type else ""))
    return out


def read_scores(path, run):
    """summary.json (None when unreadable); its evaluations fill in the vehicles that the log
    has none for."""
    try:
        data = read_summary(path)
    except (OSError, ValueError) as e:
        warn("cannot read summary %s: %s" % (path, e))
        return None
    for kv in summary_evals(data):
        if kv.get("vname") and kv["vname"] not in run.evals:
            run.evals[kv["vname"]] = kv
    return data
