#!/usr/bin/env python3
"""tools/render_mission.py on synthetic runs of thousands of objects and up to 60 vehicles
(synthetic_field.py), checked structurally: the field view, nothing per object, the legend,
everything inside the 1200 x 900 frame (and the PNG when rsvg-convert is installed), the
SVG's size.
"""

import os
import re
import shutil
import tempfile
import unittest
import xml.etree.ElementTree as ET

from render_support import (
    FIELD_SVG_ELEMENTS_MAX, LARGE_OBJECTS, LARGE_VEHICLES, SVG_BYTES_PER_OBJECT_MAX, SVG_NS,
    FrameChecks, count, data_counts, synthetic_run, text_bounds)


class RenderLargeField(unittest.TestCase, FrameChecks):
    """5,000 objects and six vehicles: the field view."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="render_large_")
        cls.objects, cls.result, cls.svg, cls.svg_path = synthetic_run(
            cls.dir, LARGE_OBJECTS, LARGE_VEHICLES, ())
        with open(os.path.join(cls.dir, "run.alog")) as f:
            cls.alog = f.read()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_runs_cleanly(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr.decode())
        self.assertEqual(self.result.stderr.decode(), "")

    def test_thousands_of_objects_get_the_field_view(self):
        self.assertIn('data-detail="field"', self.svg)
        self.assertIn("field view: 5,000 objects, no labels (more than 300)", self.svg)

    def test_no_per_object_labels_or_elements(self):
        self.assertEqual(count(self.svg, r'class="label"'), 0)
        self.assertEqual(count(self.svg, r'class="marker '), 0)
        self.assertEqual(count(self.svg, r'class="(detection|classification|reported)'), 0)
        self.assertLess(count(self.svg, r"<[a-z]"), FIELD_SVG_ELEMENTS_MAX)

    def test_every_object_has_a_marker_in_a_few_paths(self):
        hazards = sum(1 for o in self.objects if o["hazard"])
        self.assertEqual(data_counts(self.svg, "markers hazard"), hazards)
        self.assertEqual(data_counts(self.svg, "markers benign"), len(self.objects) - hazards)
        # benign fills 1 - hr binned by tenths: at most 11 paths, plus one for the hazards
        self.assertLessEqual(count(self.svg, r'class="markers '), 12)

    def test_one_cue_dot_per_cued_position_coloured_by_its_latest_cue(self):
        latest = {}
        for m in re.finditer(r"VIEW_CIRCLE +\S+ +x=(\d+),y=(-?\d+),radius=10,vertices=(\d+),"
                             r"edge_color=(\w+),fill_color=(\w+)", self.alog):
            x, y, vertices, edge, fill = m.groups()
            if vertices == "5":
                latest[(x, y)] = "pink" if fill == "pink" else \
                    "classification hazard" if edge == "yellow" else "classification benign"
            elif (x, y) not in latest:
                latest[(x, y)] = "detection"
        self.assertGreater(len(latest), 1000)
        for cls in ("classification hazard", "classification benign", "pink", "detection"):
            self.assertEqual(data_counts(self.svg, "cues " + cls),
                             sum(1 for c in latest.values() if c == cls), cls)

    def test_hazards_missed_by_the_last_report_are_ringed(self):
        report = re.search(r"HAZARDSET_REPORT +\S+ +(\S+)", self.alog).group(1)
        reported = set(re.findall(r"label=(\w+)", report))
        missed = [o for o in self.objects if o["hazard"] and o["label"] not in reported]
        self.assertGreater(len(missed), 10)
        self.assertEqual(data_counts(self.svg, "missed"), len(missed))

    def test_legend_lists_what_the_field_view_draws_with_counts(self):
        entries = re.findall(r'class="legend-entry">([^<]*)<', self.svg)
        hazards = sum(1 for o in self.objects if o["hazard"])
        expected = ["hazard (ground truth): {:,}".format(hazards),
                    "benign object (fill 1 - hr): {:,}".format(len(self.objects) - hazards),
                    "search region", "track, swath coverage (colour above)",
                    "detected, not classified: ", "classified hazard (last answer): ",
                    "classified benign (last answer): ", "last cue changed by aspect: ",
                    "hazard missed by the last report: {:,}".format(data_counts(self.svg,
                                                                                 "missed"))]
        self.assertEqual(len(entries), len(expected), entries)
        for entry, start in zip(entries, expected):
            self.assertTrue(entry.startswith(start), (entry, start))

    def test_every_vehicle_has_a_track_coverage_and_a_score(self):
        for i in range(LARGE_VEHICLES):
            name = "v%02d" % (i + 1)
            self.assertEqual(count(self.svg, r'class="track" data-vehicle="%s"' % name), 1)
            self.assertEqual(count(self.svg, r'<g class="swath" data-vehicle="%s"' % name), 1)
            self.assertEqual(count(self.svg, r'class="score" data-vehicle="%s"' % name), 1)

    def test_tracks_keep_only_the_points_a_pixel_shows(self):
        # Straight lanes sampled every 10 m: only the turns remain, two points per lane.
        for points in re.findall(r'class="track" data-vehicle="[^"]*" points="([^"]*)"', self.svg):
            self.assertLessEqual(len(points.split()), 2 * 5)

    def test_everything_outside_the_map_is_inside_the_frame(self):
        self.assert_inside_the_frame(self.svg)

    def test_nothing_is_drawn_beyond_the_frame(self):
        self.assert_nothing_drawn_beyond_the_frame(self.svg)

    def test_svg_size_stays_small(self):
        size = os.path.getsize(self.svg_path)
        self.assertLess(size, SVG_BYTES_PER_OBJECT_MAX * LARGE_OBJECTS, size)

    def test_png_is_written(self):
        if shutil.which("rsvg-convert") is None:
            self.skipTest("rsvg-convert is not installed")
        with open(os.path.splitext(self.svg_path)[0] + ".png", "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


class RenderManyVehicles(unittest.TestCase, FrameChecks):
    """The panel with more vehicles than the full score block can hold."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="render_vehicles_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def test_fourteen_vehicles_get_one_table_row_each_inside_the_frame(self):
        _objects, result, svg, _path = synthetic_run(self.dir, 2000, 14)
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        self.assertEqual(count(svg, r'class="score" data-vehicle="v\d\d"'), 14)
        self.assertNotIn("more vehicles", svg)
        self.assertIn("sensor (all): swath 40 m, pd 0.9, pfa 0.5, pclass 0.75", svg)
        self.assertEqual(len(re.findall(r'class="legend-entry"', svg)), 9)
        self.assert_inside_the_frame(svg)
        self.assert_nothing_drawn_beyond_the_frame(svg)

    def test_sixty_vehicles_show_as_many_as_fit_and_count_the_rest(self):
        _objects, result, svg, _path = synthetic_run(self.dir, 1000, 60)
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        shown = count(svg, r'class="score" data-vehicle="v\d\d"')
        more = re.search(r"\+(\d+) more vehicles", svg)
        self.assertIsNotNone(more)
        self.assertGreater(shown, 10)
        self.assertEqual(shown + int(more.group(1)), 60)
        self.assertEqual(len(re.findall(r'class="legend-entry"', svg)), 9)
        self.assert_inside_the_frame(svg)
        self.assert_nothing_drawn_beyond_the_frame(svg)

    def test_long_names_and_title_are_fitted_inside_the_frame(self):
        for n_vehicles in (2, 5):   # the full score block, then the table
            _objects, result, svg, _path = synthetic_run(
                self.dir, 400, n_vehicles, ("--no-png", "--title", "A title far too long " * 6),
                name_prefix="autonomous_survey_vehicle_with_a_long_name_")
            self.assertEqual(result.returncode, 0, result.stderr.decode())
            self.assertTrue("\u2026" in svg, "no text was cut to fit")
            self.assert_inside_the_frame(svg)
            self.assert_nothing_drawn_beyond_the_frame(svg)

    def test_vehicle_names_on_the_map_stay_inside_it_and_apart(self):
        _objects, _result, svg, _path = synthetic_run(self.dir, 1000, 14)
        boxes = [text_bounds(el) for el in ET.fromstring(svg).iter(SVG_NS + "text")
                 if el.get("class") == "vehicle-name"]
        self.assertGreater(len(boxes), 3)
        for i, a in enumerate(boxes):
            self.assertTrue(20 <= a[0] and a[2] <= 840 and 60 <= a[1] and a[3] <= 880, a)
            for b in boxes[i + 1:]:
                apart = a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1]
                self.assertTrue(apart, (a, b))


if __name__ == "__main__":
    unittest.main(verbosity=2)
