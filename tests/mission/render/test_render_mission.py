#!/usr/bin/env python3
"""Tests of tools/render_mission.py. Usage: test_render_mission.py PATH/TO/render_mission.py"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

TOOL = None  # set from argv in __main__

HAZARDS = """// gen_hazards --polygon=0,0:200,0:200,-150:0,-150 --objects=3,hazard
region = pts={0,0:200,0:200,-150:0,-150}
hazard = x=20,y=-20,label=h1,type=hazard
hazard = x=100,y=-50,label=h2,type=hazard
hazard = x=180,y=-120,label=h3,type=hazard
hazard = x=50,y=-100,label=b1,type=benign,hr=0.8
hazard = x=150,y=-30,label=b2,type=benign
hazard = x=120,y=-140,label=b3,type=benign // a comment
hazard = x=10,y=-140,label=b4,type=benign
"""

# archie: sensor swath rectangles in the log (one of them red: sensor off); betty: only an ack,
# so its coverage comes from its track. Three malformed lines (a bad time, a short line, a bad
# NODE_REPORT) and one unknown variable.
ALOG = """%% LOG FILE:       synthetic.alog
%% LOGSTART           1700000000.0
%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%
0.000      VIEW_MARKER          uFldHazardSensor x=20,y=-20,width=8,primary_color=green,type=triangle,label=h1
0.000      VIEW_MARKER          uFldHazardSensor x=50,y=-100,width=8,primary_color=light_blue,type=square,label=b1,fill_transparency=0.2
0.000      VIEW_POLYGON         uFldHazardMetric pts={0,0:200,0:200,-150:0,-150},label=search_region,edge_color=gray45,vertex_size=0,edge_size=1,fill_transparency=0
1.000      UHZ_CONFIG_ACK_BETTY uFldHazardSensor vname=betty,width=10,pd=0.9,pfa=0.531,pclass=0.93
1.000      NODE_REPORT          uSimSurvey       NAME=archie,X=0,Y=-25,SPD=1.5,HDG=90,TIME=1
2.000      NODE_REPORT          uSimSurvey       NAME=archie,X=50,Y=-25,SPD=1.5,HDG=90,TIME=2
2.000      VIEW_POLYGON         uFldHazardSensor pts={52.5,0:52.5,-50:47.5,-50:47.5,0},label=sensor_swath_archie,msg=0.90,edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2
3.000      NODE_REPORT          uSimSurvey       NAME=archie,X=100,Y=-25,SPD=1.5,HDG=90,TIME=3
3.000      VIEW_POLYGON         uFldHazardSensor pts={102.5,0:102.5,-50:97.5,-50:97.5,0},label=sensor_swath_archie,msg=0.90,edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2
3.500      VIEW_POLYGON         uFldHazardSensor pts={122.5,0:122.5,-50:117.5,-50:117.5,0},label=sensor_swath_archie,msg=0.90,edge_color=green,fill_color=red,vertex_size=0,edge_size=0,fill_transparency=0.2
4.000      NODE_REPORT          uSimSurvey       NAME=betty,X=100,Y=-100,SPD=1.5,HDG=0,TIME=4
5.000      NODE_REPORT          uSimSurvey       NAME=betty,X=100,Y=-60,SPD=1.5,HDG=0,TIME=5
6.000      NODE_REPORT          uSimSurvey       NAME=betty,X=100,Y=-20,SPD=1.5,HDG=0,TIME=6
7.000      VIEW_CIRCLE          uFldHazardSensor x=20,y=-20,radius=10,vertices=12,edge_color=white,fill_color=white,time=7,vertex_size=0,edge_size=1,fill_transparency=0.3
7.000      VIEW_CIRCLE          uFldHazardSensor x=100,y=-50,radius=10,vertices=12,edge_color=white,fill_color=white,time=7,vertex_size=0,edge_size=1,fill_transparency=0.3
7.000      VIEW_CIRCLE          uFldHazardSensor x=150,y=-30,radius=10,vertices=12,edge_color=pink,fill_color=pink,time=7,vertex_size=0,edge_size=1,fill_transparency=0.3
7.000      VIEW_CIRCLE          uFldHazardSensor x=50,y=-100,radius=10,vertices=12,edge_color=white,fill_color=white,time=7,vertex_size=0,edge_size=1,fill_transparency=0.3
8.000      VIEW_CIRCLE          uFldHazardSensor x=20,y=-20,radius=10,vertices=5,edge_color=yellow,fill_color=yellow,time=8,vertex_size=0,edge_size=1,fill_transparency=0.3
8.000      VIEW_CIRCLE          uFldHazardSensor x=100,y=-50,radius=10,vertices=5,edge_color=yellow,fill_color=yellow,time=8,vertex_size=0,edge_size=1,fill_transparency=0.3
8.000      VIEW_CIRCLE          uFldHazardSensor x=150,y=-30,radius=10,vertices=5,edge_color=green,fill_color=green,time=8,vertex_size=0,edge_size=1,fill_transparency=0.3
8.000      VIEW_CIRCLE          uFldHazardSensor x=50,y=-100,radius=10,vertices=5,edge_color=yellow,fill_color=pink,time=8,vertex_size=0,edge_size=2,fill_transparency=0.5
notanumber NODE_REPORT          uSimSurvey       NAME=archie,X=1,Y=1,SPD=1,HDG=0
9.000      NODE_REPORT
9.500      NODE_REPORT          uSimSurvey       NAME=archie,Y=1,SPD=1,HDG=0
9.600      SOMETHING_ELSE       pWhatever        anything at all
10.000     HAZARDSET_REPORT     pHazardMgr       source=betty#name=betty#x=20,y=-20,label=h1#x=100,y=-50,label=h2#x=50,y=-100,label=b1
10.000     HAZARDSET_EVAL       uFldHazardMetric vname=betty,total_score=110,norm_score=73.33,score_missed_hazards=100,score_false_alarms=10,score_time_overage=0,total_objects=3,total_time=0,received_time=10,start_time=0,missed_hazards=1,correct_hazards=2,false_alarms=1,penalty_false_alarm=10,penalty_missed_hazard=100,penalty_max_time_over=0,penalty_max_time_rate=0,max_time=0
"""


def run_tool(workdir, alog_text, hazards_text=HAZARDS, extra=()):
    alog = os.path.join(workdir, "run.alog")
    hazards = os.path.join(workdir, "hazards.txt")
    svg = os.path.join(workdir, "out.svg")
    with open(alog, "w") as f:
        f.write(alog_text)
    if hazards_text is not None:
        with open(hazards, "w") as f:
            f.write(hazards_text)
    command = [sys.executable, TOOL, "--alog", alog, "--hazards", hazards, "--svg", svg, *extra]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=100)
    svg_text = ""
    if os.path.exists(svg):
        with open(svg) as f:
            svg_text = f.read()
    return result, svg_text, svg


def count(svg, pattern):
    return len(re.findall(pattern, svg))


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
        self.assertEqual(b2.group(2), "0.50")                 # no hr: 1 - 0.5 (spec 5.4)
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
    TOOL = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
