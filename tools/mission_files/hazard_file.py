"""Hazard files, the ground truth of a field (docs/hazard-file.md), read by the rules of the
sensor's own loader (src/hazard/hazard_field.cpp, src/hazard/messages/hazard_line.cpp), so a
tool sees the field the sensor saw.

Lines: `hazard = <object>` (the word `hazard` in any case), `region = pts={...}`, `source = ...`,
comments from `//`, blank lines; anything else is a warning. An object is a comma list of
case-insensitive keys with trimmed values. A line is rejected (with a warning naming file, line,
field and value) when x, y, label or type is missing, a number is not a finite number (`nan`
is not), hr is outside [0, 1], the aspect fields are out of range, or its label was loaded
before. A bad shape or width hint is dropped with a warning. Not done here: objects given only
by lat/lon are rejected (placing them needs the mission's origin), and colour words are kept as
written (the picture maps them).
"""

from .text import (escape_for_log, excerpt, log_excerpt, parse_bool, parse_number, parse_points,
                   split_key_values, to_lower)

KNOWN_SHAPES = ("circle", "square", "diamond", "triangle", "efield", "gateway")
# (low, high, high included) per ranged key (differences.md D27, D28).
RANGES = {"hr": (0.0, 1.0, True), "aspect": (0.0, 360.0, False),
          "aspect_min": (0.0, 90.0, True), "aspect_max": (0.0, 90.0, True)}
MAX_ASPECT_WINDOW_DEG = 90.0
MAX_LABEL_BYTES = 256            # as hazard::kMaxLabelBytes
MAX_OBJECT_COORDINATE_M = 1.0e8  # as hazard::kMaxObjectCoordinate_m
BYTE_ORDER_MARK = "\ufeff"      # accepted at the start, as by the sensor


class HazardFile:
    """objects: dicts with x, y, label, type ("hazard"/"benign"), hazard (bool), hr, aspect,
    aspect_min, aspect_max, width (floats or None), color, shape, source (text or None);
    region: [(x, y)] or None; source: the `source =` text or None; warnings: texts."""

    def __init__(self):
        self.objects = []
        self.region = None
        self.source = None
        self.warnings = []


def fmt(value):
    """base::fmt(value): at most 5 decimals, trailing zeros dropped."""
    text = ("%.5f" % value).rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def field_value(key, value):
    return "field '%s' value '%s'" % (key, log_excerpt(value))


class ObjectReader:
    """One `hazard =` line's fields; `error` is the first reason to reject it."""

    def __init__(self):
        self.error = None
        self.warnings = []
        self.fields = {}
        self.type_from_hazard_key = None

    def reject(self, why):
        if self.error is None:
            self.error = why

    def number(self, key, value):
        v = parse_number(value)
        if v is None:
            self.reject(field_value(key, value) + " is not a number")
        return v

    def ranged(self, key, value):
        v = self.number(key, value)
        lo, hi, hi_included = RANGES[key]
        if v is not None and (v < lo or v > hi or (not hi_included and v == hi)):
            self.reject("%s is outside [%s, %s%s" % (field_value(key, value), fmt(lo), fmt(hi),
                                                      "]" if hi_included else ")"))
            return None
        return v

    def read(self, raw_key, value):
        key = to_lower(raw_key)
        if key in ("x", "y"):
            self.fields[key] = self.number(key, value)
        elif key == "label":
            self.read_label(key, value)
        elif key in ("source", "color", "lat", "lon"):
            self.fields[key] = value
        elif key == "type":
            kind = to_lower(value)
            if kind in ("hazard", "benign"):
                self.fields["type"] = kind
            else:
                self.reject(field_value(key, value) + " is neither 'hazard' nor 'benign'")
        elif key == "hazard":
            b = parse_bool(value)
            if b is None:
                self.reject(field_value(key, value) + " is not a boolean word")
            else:
                self.type_from_hazard_key = "hazard" if b else "benign"
        elif key in RANGES:
            self.fields[key] = self.ranged(key, value)
        elif key == "shape":
            if to_lower(value) in KNOWN_SHAPES:
                self.fields["shape"] = to_lower(value)
            else:
                self.warnings.append(field_value(key, value) +
                                     " is not a known shape; hint ignored")
        elif key == "width":
            w = parse_number(value)
            if w is not None and w >= 0.0:
                self.fields["width"] = w
            else:
                self.warnings.append(field_value(key, value) +
                                     " is not a number >= 0; hint ignored")
        else:
            self.warnings.append("unknown key '%s' (value '%s') ignored"
                                 % (escape_for_log(raw_key), log_excerpt(value)))

    def read_label(self, key, value):
        """A label reaches postings and logs: no control bytes, at most MAX_LABEL_BYTES."""
        if any(ord(c) < 0x20 or c == "\x7f" for c in value):
            self.reject(field_value(key, value) + " contains a control byte")
        if len(value.encode("utf-8")) > MAX_LABEL_BYTES:
            self.reject(field_value(key, value) + " is longer than %d bytes (kMaxLabelBytes)"
                        % MAX_LABEL_BYTES)
        self.fields["label"] = value

    def check_aspect_window(self):
        lo, hi = self.fields.get("aspect_min"), self.fields.get("aspect_max")
        if lo is not None and hi is not None and lo > hi:
            self.reject("aspect_min %s is greater than aspect_max %s" % (fmt(lo), fmt(hi)))
        elif lo is not None and hi is not None and lo + hi > MAX_ASPECT_WINDOW_DEG:
            self.reject("aspect_min + aspect_max = %s exceeds 90" % fmt(lo + hi))
        present = sum(1 for k in ("aspect", "aspect_min", "aspect_max") if k in self.fields)
        if 0 < present < 3:
            self.warnings.append(
                "partial aspect data (aspect, aspect_min and aspect_max are needed together); "
                "the object loads without aspect sensitivity")

    def finish(self):
        """The object as a dict, or None (then `error` says why)."""
        f = self.fields
        if self.error is None and ("x" not in f or "y" not in f):
            if "lat" in f and "lon" in f:
                self.reject("position given only as lat/lon cannot be placed (the tools know "
                            "no mission origin)")
            else:
                self.reject("missing field '%s'" % ("x" if "x" not in f else "y"))
        if self.error is None and max(abs(f["x"]), abs(f["y"])) > MAX_OBJECT_COORDINATE_M:
            self.reject("position (%g, %g) is beyond %d m from the origin "
                        "(kMaxObjectCoordinate_m)" % (f["x"], f["y"], MAX_OBJECT_COORDINATE_M))
        kind = f.get("type") or self.type_from_hazard_key
        if self.error is None and kind is None:
            self.reject("missing field 'type'")
        if self.error is None and not f.get("label"):
            self.reject("missing field 'label'")
        if self.error is None:
            self.check_aspect_window()
        if self.error is not None:
            return None
        return {"x": f["x"], "y": f["y"], "label": f["label"], "type": kind,
                "hazard": kind == "hazard", "hr": f.get("hr"), "aspect": f.get("aspect"),
                "aspect_min": f.get("aspect_min"), "aspect_max": f.get("aspect_max"),
                "color": f.get("color"), "shape": f.get("shape"), "width": f.get("width"),
                "source": f.get("source")}


MAX_WARNINGS_PER_LINE = 8     # as base::kMaxWarningsPerLine
MAX_WARNINGS_PER_FILE = 100   # as base::kMaxWarningsPerKind
MAX_KEYS_TRACKED = 64         # keys remembered to warn of a repeat (as the C++ reader)


class BoundedWarnings:
    """The first `limit` warnings kept, the others counted: a line of a million unknown keys
    costs a few warnings and a count, not a million (as base::WarningBudget)."""

    def __init__(self, limit):
        self.kept, self.dropped, self.limit = [], 0, limit

    def append(self, text):
        if len(self.kept) < self.limit:
            self.kept.append(text)
        else:
            self.dropped += 1

    def texts(self, what):
        more = ["... and %d more %s" % (self.dropped, what)] if self.dropped else []
        return self.kept + more


def parse_object(spec):
    """(object dict or None, error text or None, [warnings]) for the text after `hazard =`."""
    reader = ObjectReader()
    reader.warnings = BoundedWarnings(MAX_WARNINGS_PER_LINE)
    seen = set()
    for key, value, has_equals in split_key_values(spec):
        if not has_equals:
            reader.warnings.append("piece '%s' has no '='; ignored" % log_excerpt(key))
            continue
        if len(seen) < MAX_KEYS_TRACKED:   # as the sensor: a key is checked while there is room
            if to_lower(key) in seen:
                reader.warnings.append("key '%s' repeated; the later value is used"
                                       % escape_for_log(key))
            seen.add(to_lower(key))
        reader.read(key, value)
    obj = reader.finish()
    return obj, reader.error, reader.warnings.texts("warnings on this line")


def parse_hazard_text(text, name):
    """A HazardFile from the text of a file called `name` (in the warnings)."""
    result, labels = HazardFile(), set()
    result.warnings = BoundedWarnings(MAX_WARNINGS_PER_FILE)
    if text.startswith(BYTE_ORDER_MARK):
        text = text[len(BYTE_ORDER_MARK):]
    for line_no, raw in enumerate(text.split("\n"), 1):
        place = "%s:%d: " % (name, line_no)
        line = raw.split("//", 1)[0].strip(" \t\r\n")
        if not line:
            continue
        key, equals, value = line.partition("=")
        key = to_lower(key.strip(" \t\r\n"))
        if equals and key == "hazard":
            obj, error, warnings = parse_object(value)
            for w in warnings:
                result.warnings.append(place + w)
            if obj is None:
                result.warnings.append(place + error + "; line rejected")
            elif obj["label"] in labels:
                result.warnings.append(place + "duplicate label '%s'; the first object with this "
                                       "label is kept, this line is rejected" % obj["label"])
            else:
                labels.add(obj["label"])
                result.objects.append(obj)
        elif equals and key == "region":
            result.region = parse_points(value)
            if result.region is None:
                result.warnings.append(place + "bad region '%s'" % excerpt(value.strip()))
        elif equals and key == "source":
            result.source = value.strip(" \t\r\n")
        else:
            result.warnings.append(place + "unrecognised line '%s' ignored (expected 'hazard = "
                                   "...', 'region = ...' or 'source = ...')" % log_excerpt(line))
    bounded = result.warnings
    result.warnings = bounded.kept + (["%s: ... and %d more warnings" % (name, bounded.dropped)]
                                      if bounded.dropped else [])
    return result


def read_hazard_file(path):
    """The HazardFile at `path`; an unreadable file raises OSError."""
    with open(path, encoding="utf-8", errors="replace", newline="\n") as f:
        return parse_hazard_text(f.read(), path)
