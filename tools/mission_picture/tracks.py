"""Vehicle tracks: swath coverage, the tracks themselves and each vehicle's end point and name."""

from xml.sax.saxutils import escape

from .geometry import extend_ends, pixel_path, swath_strips, turn_rate_flags
from .layout import MAP_BACKGROUND, MAP_H, MAP_W, MAP_X, MAP_Y, TRACK_STEP_PX
from .scale import NORTH_PLATE_BOX, scale_plate_box
from .text_fit import text_width_px


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
