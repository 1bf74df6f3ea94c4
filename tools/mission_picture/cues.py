"""Detections and classifications: the viewer's cues (VIEW_CIRCLE, else rebuilt from the
reports), as posted or as one dot per cued object."""

from .colours import svg_colour
from .geometry import regular_polygon
from .layout import DETECTION_RADIUS_M
from .run_log import report_positions


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
