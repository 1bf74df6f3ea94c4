"""Colours: MOOS colour words as SVG colours, one colour per vehicle, readable names."""

import colorsys
import re
from functools import lru_cache

from .layout import GOLDEN_ANGLE_DEG, LIGHT_LUMINANCE, MAP_BACKGROUND, VEHICLE_COLOURS

CSS_NAMES = {"lightblue", "green", "yellow", "white", "pink", "red", "blue", "orange", "black",
             "gray", "grey", "darkgreen", "lightgreen", "cyan", "magenta", "purple", "brown",
             "gold", "navy", "violet", "khaki", "salmon", "tan", "teal", "olive", "silver",
             "darkblue", "lightgray", "lightgrey", "darkgray", "darkgrey", "hotpink", "coral",
             "crimson", "turquoise", "lime", "maroon", "beige", "ivory", "orchid", "plum"}
GREY_WORD = re.compile(r"^gr[ae]y(\d{1,3})$")
HEX_WORD = re.compile(r"^hex:([0-9a-f]{2}),([0-9a-f]{2}),([0-9a-f]{2})$")
LETTERS_WORD = re.compile(r"^[a-z]+$")


@lru_cache(maxsize=256)  # a log repeats a handful of colour words thousands of times
def svg_colour(moos, fallback="#999999"):
    """A MOOS colour word (manual colour appendix) as an SVG colour."""
    if not moos:
        return fallback
    word = moos.strip().lower().replace("_", "")
    m = GREY_WORD.match(word)
    if m and int(m.group(1)) <= 100:
        level = round(int(m.group(1)) * 255 / 100)
        return "#%02x%02x%02x" % (level, level, level)
    m = HEX_WORD.match(word)
    if m:
        return "#" + "".join(m.groups())
    if word in ("invisible", "empty"):
        return "none"
    if LETTERS_WORD.match(word):
        return word if word in CSS_NAMES or len(word) > 2 else fallback
    return fallback


def vehicle_colour(index):
    """The palette first; past it, hues a golden angle apart (distinct for any count)."""
    if index < len(VEHICLE_COLOURS):
        return VEHICLE_COLOURS[index]
    hue = ((index - len(VEHICLE_COLOURS)) * GOLDEN_ANGLE_DEG + 20.0) % 360.0 / 360.0
    r, g, b = colorsys.hsv_to_rgb(hue, 0.55, 1.0)
    return "#%02x%02x%02x" % (round(r * 255), round(g * 255), round(b * 255))


def is_light(colour):
    """True for a #rrggbb colour too light to read on the light panel without a dark outline."""
    if not (colour.startswith("#") and len(colour) == 7):
        return False
    r, g, b = (int(colour[i:i + 2], 16) / 255.0 for i in (1, 3, 5))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b > LIGHT_LUMINANCE


def name_outline(colour):
    """SVG attributes that make a vehicle's name readable on the light panel."""
    if is_light(colour):
        return ' stroke="%s" stroke-width="2.5" paint-order="stroke"' % MAP_BACKGROUND
    return ' stroke="#444" stroke-width="0.3"'
