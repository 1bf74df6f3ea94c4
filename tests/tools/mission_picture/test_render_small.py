#!/usr/bin/env python3
"""tools/render_mission.py on a small hand-written run (the "objects" level of detail): markers,
cues, tracks, swaths, rings, score, stderr warnings and the PNG (RenderSynthetic); empty,
garbage and missing inputs and the scores from summary.json (RenderRobustness).
"""

import os
import re
import shutil
import tempfile
import unittest

from render_support import ALOG, HAZARDS, count, run_tool


class RenderSynthetic(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="render_test_")
        cls.result, cls.svg, cls.svg_path = run_tool(cls.dir, ALOG)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_exit_code_is_zero(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr.decode())

    def test_markers_for_every_object_in_the_hazard_file(self):
        self.assertEqual(count(self.svg, r'class="marker hazard"'), 3)
        self.assertEqual(count(self.svg, r'class="marker benign"'), 4)

    def test_few_objects_get_the_objects_view_with_a_label_each(self):
        self.assertIn('data-detail="objects"', self.svg)
        self.assertEqual(count(self.svg, r'class="label"'), 7)

    def test_view_marker_styles_win_and_benign_alpha_is_one_minus_hr(self):
        b1 = re.search(r'<polygon class="marker benign" data-label="b1" points="([^"]*)" '
                       r'fill="([^"]*)" fill-opacity="([^"]*)"', self.svg)
        self.assertIsNotNone(b1)
        self.assertEqual(len(b1.group(1).split()), 4)        # VIEW_MARKER says square
        self.assertEqual(b1.group(2), "lightblue")
        self.assertEqual(b1.group(3), "0.20")                 # VIEW_MARKER's fill_transparency
        b2 = re.search(r'data-label="b2" points="([^"]*)" fill="[^"]*" fill-opacity="([^"]*)"',
                       self.svg)
        self.assertEqual(len(b2.group(1).split()), 3)         # default benign shape: triangle
        self.assertEqual(b2.group(2), "0.50")                 # no hr: 1 - 0.5 (docs/messages.md)
        h1 = re.search(r'data-label="h1" points="[^"]*" fill="([^"]*)"', self.svg)
        self.assertEqual(h1.group(1), "green")                # D17

    def test_detection_and_classification_cues_follow_d19(self):
        self.assertEqual(count(self.svg, r'class="detection[" ]'), 4)
        self.assertEqual(count(self.svg, r'class="detection pink"'), 1)
        self.assertEqual(count(self.svg, r'class="classification hazard[" ]'), 3)
        self.assertEqual(count(self.svg, r'class="classification benign"'), 1)
        self.assertEqual(count(self.svg, r'class="classification hazard pink"'), 1)
        # 12-vertex detection circles, 5-vertex classification pentagons.
        det = re.search(r'class="detection" points="([^"]*)"', self.svg)
        self.assertEqual(len(det.group(1).split()), 12)
        cls = re.search(r'class="classification hazard" points="([^"]*)"', self.svg)
        self.assertEqual(len(cls.group(1).split()), 5)

    def test_both_tracks_and_their_swath_coverage(self):
        self.assertEqual(count(self.svg, r'class="track" data-vehicle="archie"'), 1)
        self.assertEqual(count(self.svg, r'class="track" data-vehicle="betty"'), 1)
        archie = re.search(r'<g class="swath" data-vehicle="archie"[^>]*>(.*?)</g>', self.svg, re.S)
        # The red (sensor off) rectangle is left out.
        self.assertEqual(count(archie.group(1), r"<polygon"), 2)
        betty = re.search(r'<g class="swath" data-vehicle="betty"[^>]*>(.*?)</g>', self.svg, re.S)
        self.assertEqual(count(betty.group(1), r"<polyline"), 1)  # track widened to the acked width
        width = float(re.search(r'stroke-width="([0-9.]+)"', betty.group(1)).group(1))
        self.assertGreater(width, 0)

    def test_report_rings_and_missed_hazards(self):
        self.assertEqual(count(self.svg, r'class="reported"'), 3)
        self.assertEqual(count(self.svg, r'class="missed"'), 1)   # h3 was not reported

    def test_region_scale_bar_north_arrow_and_score(self):
        self.assertEqual(count(self.svg, r'class="region"'), 1)
        self.assertEqual(count(self.svg, r'class="scale-bar"'), 1)
        self.assertEqual(count(self.svg, r'class="north-arrow"'), 1)
        self.assertIn("73.33 / 100", self.svg)
        self.assertIn("sensor: swath 10 m, pd 0.9, pfa 0.531, pclass 0.93", self.svg)

    def test_malformed_lines_are_named_on_stderr(self):
        err = self.result.stderr.decode()
        self.assertIn("run.alog:25: malformed line", err)
        self.assertIn("run.alog:26: malformed line", err)
        self.assertIn("run.alog:27: NODE_REPORT without NAME, X and Y", err)
        self.assertNotIn("SOMETHING_ELSE", err)  # unknown variables are not problems

    def test_png_is_written_when_rsvg_convert_exists(self):
        png = os.path.splitext(self.svg_path)[0] + ".png"
        if shutil.which("rsvg-convert") is None:
            self.skipTest("rsvg-convert is not installed")
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


class RenderRobustness(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="render_test_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def test_empty_log_and_empty_hazard_file(self):
        result, svg, _ = run_tool(self.dir, "", "", ("--no-png",))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        self.assertIn("no objects and no tracks", svg)
        self.assertTrue(svg.rstrip().endswith("</svg>"))

    def test_garbage_log_and_missing_hazard_file(self):
        garbage = "\x00\x01 binary \xff\n%%\n1.0\n1.0 VIEW_CIRCLE src x=abc\n" \
                  "2.0 HAZARDSET_REPORT src #x=1,y=2,label=3\n3.0 HAZARDSET_EVAL src norm_score=5\n"
        result, svg, _ = run_tool(self.dir, garbage, None, ("--no-png",))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        err = result.stderr.decode()
        self.assertIn("cannot read hazard file", err)
        self.assertIn("run.alog:3: malformed line", err)
        self.assertIn("run.alog:4: VIEW_CIRCLE without x and y", err)
        self.assertIn("run.alog:5: HAZARDSET_REPORT without source", err)
        self.assertIn("run.alog:6: HAZARDSET_EVAL without vname", err)
        self.assertTrue(svg.rstrip().endswith("</svg>"))

    def test_nan_is_not_a_number_in_the_log_or_the_hazard_file(self):
        log = ("1 NODE_REPORT sim NAME=ann,X=nan,Y=0,SPD=1,HDG=0\n"
               "nan VIEW_CIRCLE src x=1,y=1\n"
               "2 VIEW_CIRCLE src x=inf,y=1\n")
        hazards = HAZARDS + "hazard = x=nan,y=1,label=n,type=hazard\n"
        result, svg, _ = run_tool(self.dir, log, hazards, ("--no-png",))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        err = result.stderr.decode()
        self.assertIn("run.alog:1: NODE_REPORT without NAME, X and Y skipped", err)
        # A nan time is no clock's: skipped and counted, one warning for all such lines.
        self.assertIn("run.alog: 1 line with unusable times (not finite, or beyond 1e10 s) skipped",
                      err)
        self.assertIn("run.alog:3: VIEW_CIRCLE without x and y skipped", err)
        self.assertIn("hazards.txt:10: field 'x' value 'nan' is not a number; line rejected", err)
        self.assertEqual(count(svg, r'class="marker '), 7)   # the file's seven good objects

    def test_summary_json_supplies_the_scores(self):
        summary = os.path.join(self.dir, "summary.json")
        with open(summary, "w") as f:
            f.write('{"title": "From the summary", "evals": [{"vname": "archie", '
                    '"norm_score": 91.5, "correct_hazards": 3, "missed_hazards": 0, '
                    '"false_alarms": 2}]}')
        result, svg, _ = run_tool(self.dir, "", HAZARDS, ("--no-png", "--summary", summary))
        self.assertEqual(result.returncode, 0, result.stderr.decode())
        self.assertIn("From the summary", svg)
        self.assertIn("91.5 / 100", svg)


if __name__ == "__main__":
    unittest.main(verbosity=2)
