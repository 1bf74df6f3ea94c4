"""The picture as one SVG document: the map (clipped to its viewport) and the panel."""

import os

from .colours import vehicle_colour
from .cues import derived_circles, draw_cues, draw_cues_field, latest_cues
from .detail import Detail, choose_mode
from .geometry import View
from .layout import (
    CANVAS_H, CANVAS_W, MAP_BACKGROUND, MAP_H, MAP_W, MAP_X, MAP_Y, TITLE_FONT_PX,
    TITLE_MIN_FONT_PX)
from .objects import (
    draw_objects, draw_objects_field, draw_report, draw_report_field, missed_hazards)
from .panel import draw_panel
from .scale import draw_scale_and_north
from .text_fit import svg_text
from .tracks import draw_coverage, draw_tracks, draw_vehicle_ends


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
