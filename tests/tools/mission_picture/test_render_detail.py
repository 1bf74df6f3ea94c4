#!/usr/bin/env python3
"""tools/render_mission.py: the level of detail (300 objects, or --detail), swath strips,
NODE_REPORT spellings, and which log lines are parsed at all.
"""

import re
import shutil
import tempfile
import unittest

from render_support import HAZARDS, count, data_counts, run_tool


class RenderLevelOfDetail(unittest.TestCase):
    """The level of detail follows the object count (300), or --detail."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="render_detail_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def field_of(self, n_objects, extra=()):
        lines = ["region = pts={0,0:1000,0:1000,-1000:0,-1000}"]
        lines += ["hazard = x=%d,y=%d,label=o%d,type=%s" % (
            (i * 37) % 1000, -((i * 53) % 1000), i, "hazard" if i % 5 == 0 else "benign")
            for i in range(n_objects)]
        result, svg, _ = run_tool(self.dir, "", "\n".join(lines) + "\n", ("--no-png", *extra))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        return svg

    def test_three_hundred_objects_keep_their_labels(self):
        svg = self.field_of(300)
        self.assertIn('data-detail="objects"', svg)
        self.assertEqual(count(svg, r'class="label"'), 300)

    def test_three_hundred_and_one_objects_get_the_field_view(self):
        svg = self.field_of(301)
        self.assertIn('data-detail="field"', svg)
        self.assertEqual(count(svg, r'class="label"'), 0)
        self.assertEqual(data_counts(svg, "markers hazard") + data_counts(svg, "markers benign"),
                         301)

    def test_detail_option_overrides_the_count(self):
        self.assertEqual(count(self.field_of(301, ("--detail", "objects")), r'class="label"'), 301)
        svg = self.field_of(20, ("--detail", "field"))
        self.assertIn('data-detail="field"', svg)
        self.assertIn("field view: no labels", svg)


class RenderGeometry(unittest.TestCase):
    """Swath strips, NODE_REPORT spellings, and which lines are parsed at all."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="render_geometry_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    @staticmethod
    def swath_line(t, vehicle, cx, on=True):
        # a 50 m (across) by 5 m (along) rectangle heading east, in our sensor's corner order
        return ("%.3f VIEW_POLYGON uFldHazardSensor pts={%g,-25:%g,-25:%g,25:%g,25},"
                "label=sensor_swath_%s,fill_color=%s" % (t, cx + 2.5, cx - 2.5, cx - 2.5,
                                                         cx + 2.5, vehicle,
                                                         "white" if on else "red"))

    def swath_group(self, svg, vehicle):
        m = re.search(r'<g class="swath" data-vehicle="%s"[^>]*>(.*?)</g>' % vehicle, svg, re.S)
        self.assertIsNotNone(m, vehicle)
        return m.group(1)

    def test_touching_rectangles_become_one_strip_and_gaps_break_it(self):
        lines = [self.swath_line(i, "ann", 2.0 * i) for i in range(50)]            # 2 m apart
        lines += [self.swath_line(100 + i, "bob", 30.0 * i) for i in range(4)]     # 30 m apart
        lines += [self.swath_line(200 + i, "cat", 500.0) for i in range(10)]       # standing
        lines += [self.swath_line(300, "ann", 120.0, on=False)]                    # sensor off
        result, svg, _ = run_tool(self.dir, "\n".join(lines) + "\n", HAZARDS, ("--no-png",))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        ann = self.swath_group(svg, "ann")
        self.assertEqual((count(ann, "<polyline"), count(ann, "<polygon")), (1, 0))
        points = re.search(r'points="([^"]*)"', ann).group(1).split()
        self.assertLessEqual(len(points), 3)   # a straight strip: its two ends (plus rounding)
        self.assertEqual((count(self.swath_group(svg, "bob"), "<polyline"),
                          count(self.swath_group(svg, "bob"), "<polygon")), (0, 4))
        self.assertEqual(count(self.swath_group(svg, "cat"), "<polygon"), 1)

    def test_strip_width_is_the_rectangles_across_track_side(self):
        lines = [self.swath_line(i, "ann", 2.0 * i) for i in range(50)]
        lines += ["0 NODE_REPORT sim NAME=ann,X=0,Y=-300,SPD=1,HDG=90",
                  "1 NODE_REPORT sim NAME=ann,X=0,Y=300,SPD=1,HDG=90"]
        _result, svg, _ = run_tool(self.dir, "\n".join(lines) + "\n", "", ("--no-png",))
        width_px = float(re.search(r'stroke-width="([0-9.]+)"', self.swath_group(svg, "ann"))
                         .group(1))
        bar = re.search(r'class="scale-bar">\s*<rect[^>]*/>\s*<rect[^>]*/>\s*'
                        r'<rect x="[^"]*" y="[^"]*" width="([0-9.]+)"', svg)
        label = re.search(r'text-anchor="middle">(\d+) m</text>', svg)
        px_per_m = float(bar.group(1)) / float(label.group(1))
        self.assertAlmostEqual(width_px / px_per_m, 50.0, delta=0.5)

    def test_node_reports_in_any_key_spelling_make_tracks(self):
        log = ("1 NODE_REPORT sim NAME=ann,X=0,Y=0,SPD=1,HDG=0\n"
               "2 NODE_REPORT sim NAME=ann,X=0,Y=50,SPD=1,HDG=0\n"
               "1 NODE_REPORT sim name=bob, x=10 ,y=0,speed=1,heading=0\n"
               "2 NODE_REPORT sim name=bob, x=10 ,y=50,speed=1,heading=0\n")
        result, svg, _ = run_tool(self.dir, log, HAZARDS, ("--no-png",))
        self.assertEqual(result.stderr.decode(), "")
        self.assertEqual(count(svg, r'class="track" data-vehicle="ann"'), 1)
        self.assertEqual(count(svg, r'class="track" data-vehicle="bob"'), 1)

    def test_lines_of_variables_not_drawn_are_not_parsed(self):
        log = ("garbage APPCAST src anything\n"        # not drawn: its time is never read
               "garbage NODE_REPORT src NAME=ann,X=0,Y=0\n")
        result, _svg, _ = run_tool(self.dir, log, HAZARDS, ("--no-png",))
        err = result.stderr.decode()
        self.assertNotIn("run.alog:1:", err)
        self.assertIn("run.alog:2: malformed line", err)


if __name__ == "__main__":
    unittest.main(verbosity=2)
