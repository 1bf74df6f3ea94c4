"""The scale bar and the north arrow, on plates that read over a dense field."""

from .geometry import nice_length
from .layout import MAP_BACKGROUND, MAP_H, MAP_W, MAP_X, MAP_Y
from .text_fit import text_width_px

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
