"""The field's objects (markers, labels) and the last report's rings around them."""

from xml.sax.saxutils import escape

from mission_files.text import parse_number

from .colours import svg_colour
from .geometry import marker_points
from .layout import (
    DEFAULT_MARKER_WIDTH_M, DETECTION_RADIUS_M, MIN_MARKER_PX, OPACITY_STEP, REPORT_RING_M)


def object_style(run, o, opts):
    """(shape, SVG colour, width_m, fill opacity) of an object: VIEW_MARKER, hazard file, options."""
    style = run.markers.get(o["label"], {})
    hazard = o["hazard"]
    shape = (style.get("type") or o["shape"] or
             (opts.hazard_shape if hazard else opts.benign_shape)).lower()
    col = svg_colour(style.get("primary_color") or o["color"] or
                     (opts.hazard_color if hazard else opts.benign_color))
    width = parse_number(style.get("width")) or o["width"] or DEFAULT_MARKER_WIDTH_M
    opacity = 1.0
    if not hazard:
        # A benign marker's fill_transparency (the viewer's alpha) is 1 - hr, 0.5
        # without hr. The edge is always drawn, so a fully clear fill still shows the shape.
        alpha = parse_number(style.get("fill_transparency"))
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
