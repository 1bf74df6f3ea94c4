"""Layout and style constants of the picture (pixels unless stated)."""

CANVAS_W, CANVAS_H = 1200, 900
MAP_X, MAP_Y, MAP_W, MAP_H = 20, 60, 820, 820      # the map viewport
PANEL_X = MAP_X + MAP_W + 20                        # the right-hand panel (scores, legend)
PANEL_RIGHT = CANVAS_W - 10                         # no panel text or box goes past this
PANEL_BOTTOM = CANVAS_H - 10                        # nor below this
PANEL_W = PANEL_RIGHT - PANEL_X
TITLE_FONT_PX, TITLE_MIN_FONT_PX = 24, 14
MAP_BACKGROUND = "#1b2736"                          # dark, like a viewer: white cues stay visible
VEHICLE_COLOURS = ["#ff8c42", "#e040fb", "#26c6da", "#c0ca33", "#ff5252", "#ffffff"]
GOLDEN_ANGLE_DEG = 137.508                          # hue step of the colours past the palette
SWATH_OPACITY = 0.18
LIGHT_LUMINANCE = 0.8                               # relative luminance above which a name on
                                                    # the light panel gets a dark outline
DETECTION_RADIUS_M = 10.0                           # D19; docs/messages.md
DEFAULT_MARKER_WIDTH_M = 8.0                        # manual 7.6
MIN_MARKER_PX = 7.0                                 # objects mode: a marker is never smaller
REPORT_RING_M = 15.0                                # drawn outside the radius-10 cues
SENSOR_MAX_TURN_RATE_DPS = 1.5                      # manual 8
SENSOR_MAX_SPEED_MPS = 2.0                          # differences.md D14
TURN_WINDOW_S = 2.0                                 # the 2 s turn-rate window
TRACK_STEP_PX = 1.0                                 # track points closer than this are dropped
SIMPLIFY_TOLERANCE_PX = 0.4                         # Douglas-Peucker: invisible at 1200 x 900
# Consecutive swath rectangles join into one strip while their centres are at most one swath
# length apart (they touch or overlap) plus this slack for heading noise; beyond it the strip
# breaks, because the sensor left a hole there.
SWATH_JOIN_SLACK_M = 1.0
SWATH_WIDTH_CHANGE = 0.01                           # relative width change that starts a new strip

# Level of detail. At 300 objects on the 820 px map the mean spacing is about 47 px: closer
# than that, labels (about 25 px wide) and the radius-10 m cues of neighbours start to overlap
# in the fields we generate, so beyond it the picture switches to the "field" style.
DETAIL_MAX_OBJECTS = 300
FIELD_MARKER_SPACING_FRACTION = 0.55                # marker width / mean object spacing
FIELD_MARKER_MIN_PX, FIELD_MARKER_MAX_PX = 3.0, 9.0
FIELD_HAZARD_SCALE = 1.35                           # hazards larger: they are what is searched for
FIELD_TRACK_WIDTH_PX = 1.2
OBJECTS_TRACK_WIDTH_PX = 2.0
FIELD_SWATH_OPACITY = 0.28                          # coverage reads as a layer under the dots
FIELD_CUE_DOT_FRACTION = 0.65                       # cue dot diameter / benign marker width
FIELD_MISSED_RING_FRACTION = 1.0                    # missed-hazard ring radius / hazard marker
FIELD_LEGEND_SYMBOL_SCALE = 2.0                     # legend symbols larger than on the map,
LEGEND_SYMBOL_MAX_PX = 16.0                         # but no larger than this (rows are 17-24)
FIELD_LEGEND_DOT_SCALE, LEGEND_DOT_MAX_PX = 2.5, 10.0   # the same for the cue dots
OPACITY_STEP = 0.1                                  # field style: benign fill alphas are binned
