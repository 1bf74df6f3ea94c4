"""The level of detail (objects or field) and the sizes of the field view."""

import math

from .cues import CUE_DOTS
from .layout import (
    DETAIL_MAX_OBJECTS, FIELD_CUE_DOT_FRACTION, FIELD_HAZARD_SCALE, FIELD_MARKER_MAX_PX,
    FIELD_MARKER_MIN_PX, FIELD_MARKER_SPACING_FRACTION, FIELD_MISSED_RING_FRACTION,
    FIELD_SWATH_OPACITY, FIELD_TRACK_WIDTH_PX, MAP_W, OBJECTS_TRACK_WIDTH_PX, SWATH_OPACITY)


class Detail:
    """What the picture draws for this many objects (module contract, "Two levels of detail")."""

    def __init__(self, mode, auto, view, objects, region):
        self.mode = mode
        self.auto = auto            # chosen from the object count, not by --detail
        self.field = mode == "field"
        self.labels = not self.field
        self.track_width_px = FIELD_TRACK_WIDTH_PX if self.field else OBJECTS_TRACK_WIDTH_PX
        self.swath_opacity = FIELD_SWATH_OPACITY if self.field else SWATH_OPACITY
        spacing_px = mean_spacing_px(view, objects, region)
        self.benign_px = min(FIELD_MARKER_MAX_PX, max(
            FIELD_MARKER_MIN_PX, FIELD_MARKER_SPACING_FRACTION * spacing_px))
        self.hazard_px = self.benign_px * FIELD_HAZARD_SCALE
        self.dot_px = max(1.5, self.benign_px * FIELD_CUE_DOT_FRACTION)
        self.ring_px = self.hazard_px * FIELD_MISSED_RING_FRACTION
        self.counts = {}

    def count_field(self, objects, cues, missed):
        """The numbers the field legend shows beside its symbols."""
        hazards = sum(1 for o in objects if o["hazard"])
        self.counts = {"hazard": hazards, "benign": len(objects) - hazards, "missed": len(missed)}
        for cls, _colour in CUE_DOTS:
            self.counts[cls] = 0
        for cls in cues.values():
            self.counts[cls] += 1


def choose_mode(requested, objects):
    if requested in ("objects", "field"):
        return requested
    return "field" if len(objects) > DETAIL_MAX_OBJECTS else "objects"


def mean_spacing_px(view, objects, region):
    """Mean distance between objects on the map: sqrt(area / count), area of region or extent."""
    if not objects:
        return MAP_W
    if region and len(region) >= 3:
        area_m2 = abs(sum(a[0] * b[1] - b[0] * a[1]
                          for a, b in zip(region, region[1:] + region[:1]))) / 2
    else:
        xs = [o["x"] for o in objects]
        ys = [o["y"] for o in objects]
        area_m2 = (max(xs) - min(xs)) * (max(ys) - min(ys))
    if area_m2 <= 0:
        return MAP_W
    return math.sqrt(area_m2 / len(objects)) * view.scale
