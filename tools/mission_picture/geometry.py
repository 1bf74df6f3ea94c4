"""Map geometry: the metres-to-pixels view, marker outlines, and the reduction of tracks and
swath strips to the points a pixel shows."""

import math

from .layout import (
    MAP_H, MAP_W, MAP_X, MAP_Y, SENSOR_MAX_SPEED_MPS, SENSOR_MAX_TURN_RATE_DPS,
    SIMPLIFY_TOLERANCE_PX, SWATH_JOIN_SLACK_M, SWATH_WIDTH_CHANGE, TRACK_STEP_PX, TURN_WINDOW_S)


def turn_rate_flags(track):
    """Per track sample: was the sensor on (turn rate over 2 s, speed limit)?

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
