"""The legend: one symbol and text per thing the chosen level of detail draws."""

from .colours import svg_colour
from .cues import CUE_DOTS
from .geometry import marker_points, regular_polygon
from .layout import (
    FIELD_LEGEND_DOT_SCALE, FIELD_LEGEND_SYMBOL_SCALE, LEGEND_DOT_MAX_PX, LEGEND_SYMBOL_MAX_PX,
    MAP_BACKGROUND, PANEL_W, PANEL_X, SWATH_OPACITY)
from .rows import Row
from .text_fit import svg_text


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
