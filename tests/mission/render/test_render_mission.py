#!/usr/bin/env python3
"""Tests of tools/render_mission.py.

Usage: test_render_mission.py PATH/TO/render_mission.py [unittest arguments, e.g. a class name]

RenderSynthetic and RenderRobustness: a small hand-written run (the "objects" level of detail).
RenderLargeField, RenderManyVehicles, RenderGeometry: synthetic runs of thousands of objects and
many vehicles (synthetic_field.py), checked structurally: the level of detail, what is and is not
drawn, that everything stays inside the 1200 x 900 frame, the legend, the SVG's size.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import synthetic_field  # noqa: E402  (beside this file)

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


def run_on_files(workdir, alog, hazards, extra=()):
    """Runs the tool on the files; (result, the SVG's text or "" when none was written, its path)."""
    svg = os.path.join(workdir, "out.svg")
    command = [sys.executable, TOOL, "--alog", alog, "--hazards", hazards, "--svg", svg, *extra]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=100)
    svg_text = ""
    if os.path.exists(svg):
        with open(svg) as f:
            svg_text = f.read()
    return result, svg_text, svg


def run_tool(workdir, alog_text, hazards_text=HAZARDS, extra=()):
    """Writes the log (and the hazard file, unless None) into workdir and runs the tool on them."""
    alog = os.path.join(workdir, "run.alog")
    hazards = os.path.join(workdir, "hazards.txt")
    with open(alog, "w") as f:
        f.write(alog_text)
    if hazards_text is not None:
        with open(hazards, "w") as f:
            f.write(hazards_text)
    return run_on_files(workdir, alog, hazards, extra)


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


# ---------------------------------------------------------------------------------------------
# Large fields: structural checks on synthetic runs (synthetic_field.py).

SVG_NS = "{http://www.w3.org/2000/svg}"
CANVAS_W, CANVAS_H = 1200, 900
MAP_RIGHT_PX = 840          # the map viewport ends here; the panel starts to its right
# A text's width is estimated here from typical DejaVu Sans advance widths per class of
# characters (in em; bold about 8 % wider). The tool fits its texts with upper bounds of these
# widths, 10 px inside the frame, so this check passes for any text the tool fitted and fails
# for one it did not; the raster test below checks the real glyphs.
TEST_EM = {"narrow": 0.32, "wide": 0.85, "lower": 0.58, "upper": 0.70, "digit": 0.636,
           "other": 0.70}
TEST_NARROW, TEST_WIDE, TEST_BOLD = set(" ,.:;|!'()[]-/ijlftr"), set("mwMW%@"), 1.08


def estimated_width_em(text):
    em = 0.0
    for c in text:
        em += TEST_EM["narrow" if c in TEST_NARROW else "wide" if c in TEST_WIDE else
                      "digit" if c.isdigit() else "lower" if c.islower() else
                      "upper" if c.isupper() else "other"]
    return em


SVG_BYTES_PER_OBJECT_MAX = 100      # the field view: measured about 46 per object
FIELD_SVG_ELEMENTS_MAX = 250        # the field view draws paths per style, not per object
LARGE_OBJECTS, LARGE_VEHICLES = 5000, 6


def synthetic_run(workdir, n_objects, n_vehicles, extra=("--no-png",), name_prefix="v"):
    objects = synthetic_field.write(workdir, n_objects, n_vehicles, name_prefix=name_prefix)
    result, svg, path = run_on_files(workdir, os.path.join(workdir, "run.alog"),
                                     os.path.join(workdir, "hazards.txt"), extra)
    return objects, result, svg, path


def data_counts(svg, cls):
    """Sum of data-count over the elements whose class is exactly cls."""
    return sum(int(n) for n in re.findall(r'class="%s" data-count="(\d+)"' % re.escape(cls), svg))


def text_bounds(el):
    """Estimated box of a <text>, each <tspan> at its own font size and weight."""
    font = float(el.get("font-size", "16"))
    bold = el.get("font-weight") == "bold"
    runs = [(el.text or "", font, bold)]
    for span in el.iter(SVG_NS + "tspan"):
        runs.append((span.text or "", float(span.get("font-size", font)),
                     span.get("font-weight", el.get("font-weight")) == "bold"))
        runs.append((span.tail or "", font, bold))
    width = sum(estimated_width_em(text) * size * (TEST_BOLD if heavy else 1.0)
                for text, size, heavy in runs)
    tallest = max(size for _text, size, _heavy in runs)
    x, y = float(el.get("x")), float(el.get("y"))
    anchor = el.get("text-anchor", "start")
    left = x - width if anchor == "end" else x - width / 2 if anchor == "middle" else x
    return left, y - tallest, left + width, y + tallest * 0.25


def element_bounds(el):
    """(x0, y0, x1, y1) of a drawn element, None for a group or an element without geometry."""
    tag = el.tag[len(SVG_NS):]
    f = lambda name: float(el.get(name, "0"))
    if tag == "rect":
        return f("x"), f("y"), f("x") + f("width"), f("y") + f("height")
    if tag == "circle":
        return f("cx") - f("r"), f("cy") - f("r"), f("cx") + f("r"), f("cy") + f("r")
    if tag == "line":
        return min(f("x1"), f("x2")), min(f("y1"), f("y2")), max(f("x1"), f("x2")), \
            max(f("y1"), f("y2"))
    if tag in ("polygon", "polyline"):
        xy = [tuple(map(float, p.split(","))) for p in el.get("points").split()]
        return min(p[0] for p in xy), min(p[1] for p in xy), max(p[0] for p in xy), \
            max(p[1] for p in xy)
    if tag == "text":
        return text_bounds(el)
    if tag == "path":
        raise AssertionError("a path outside the clipped map: %s" % el.get("class"))
    return None


def elements_outside_the_map(root):
    """Every element that the map's clip path does not hold inside the map viewport."""
    for child in root:
        if child.get("clip-path") or child.tag == SVG_NS + "clipPath":
            continue
        for el in child.iter():
            yield el


class FrameChecks:
    """Mixin: the frame and raster checks shared by the large-field test classes."""

    def assert_inside_the_frame(self, svg):
        root = ET.fromstring(svg)
        self.assertEqual((root.get("width"), root.get("height")), ("1200", "900"))
        checked = 0
        for el in elements_outside_the_map(root):
            box = element_bounds(el)
            if box is None:
                continue
            checked += 1
            text = "".join(el.itertext()) or el.get("class") or el.tag
            self.assertGreaterEqual(box[0], 0, text)
            self.assertGreaterEqual(box[1], 0, text)
            self.assertLessEqual(box[2], CANVAS_W, text)
            self.assertLessEqual(box[3], CANVAS_H, text)
        self.assertGreater(checked, 20)
        panel = [g for g in root if g.get("class") == "panel"]
        self.assertEqual(len(panel), 1)
        for el in panel[0].iter():
            box = element_bounds(el)
            if box is not None:   # the panel keeps to the right of the map
                self.assertGreater(box[0], MAP_RIGHT_PX, "".join(el.itertext()) or el.tag)

    def assert_nothing_drawn_beyond_the_frame(self, svg):
        """Renders the strips just right of and below the frame: they must stay transparent,
        compared byte for byte with the rendering of an empty SVG of the same size."""
        if shutil.which("rsvg-convert") is None:
            self.skipTest("rsvg-convert is not installed")
        strips = {"right": ("60", "900", "1200 0 60 900"), "below": ("1260", "60", "0 900 1260 60")}
        root_attrs = 'width="1200" height="900" viewBox="0 0 1200 900"'
        self.assertIn(root_attrs, svg)
        overflowing = svg.replace("</svg>", '<text x="1190" y="450" font-size="20">overflow'
                                  '</text><rect x="10" y="895" width="50" height="20"/></svg>')
        for name, (width, height, box) in strips.items():
            attrs = 'width="%s" height="%s" viewBox="%s"' % (width, height, box)
            empty = self.render_png('<svg xmlns="http://www.w3.org/2000/svg" %s></svg>' % attrs)
            self.assertEqual(self.render_png(svg.replace(root_attrs, attrs)), empty,
                             "something is drawn %s the 1200 x 900 frame" % name)
            # The check can fail: a picture that does overflow is caught.
            self.assertNotEqual(self.render_png(overflowing.replace(root_attrs, attrs)), empty)

    def render_png(self, svg_text):
        svg = os.path.join(self.dir, "strip.svg")
        png = os.path.join(self.dir, "strip.png")
        with open(svg, "w") as f:
            f.write(svg_text)
        subprocess.run(["rsvg-convert", "-o", png, svg], check=True, timeout=60)
        with open(png, "rb") as f:
            return f.read()


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


def truetype_advance_widths_em(path, chars):
    """Advance widths (em) of chars in a TrueType font: its cmap (platform 3, encoding 1,
    format 4) and hmtx tables, read with struct (no font library in the standard library)."""
    import struct
    with open(path, "rb") as f:
        data = f.read()
    tables = {}
    for i in range(struct.unpack(">H", data[4:6])[0]):
        tag, _sum, offset, _length = struct.unpack(">4sIII", data[12 + 16 * i:28 + 16 * i])
        tables[tag.decode("latin-1")] = offset
    units_per_em = struct.unpack(">H", data[tables["head"] + 18:tables["head"] + 20])[0]
    metrics = struct.unpack(">H", data[tables["hhea"] + 34:tables["hhea"] + 36])[0]
    advances = [struct.unpack(">H", data[tables["hmtx"] + 4 * i:tables["hmtx"] + 4 * i + 2])[0]
                for i in range(metrics)]
    cmap = tables["cmap"]
    sub = None
    for i in range(struct.unpack(">H", data[cmap + 2:cmap + 4])[0]):
        platform, encoding, offset = struct.unpack(">HHI", data[cmap + 4 + 8 * i:cmap + 12 + 8 * i])
        if (platform, encoding) == (3, 1):
            sub = cmap + offset
    segments = struct.unpack(">H", data[sub + 6:sub + 8])[0] // 2
    ends_at = sub + 14
    starts_at = ends_at + 2 * segments + 2          # a reserved pad word follows the ends
    deltas_at = starts_at + 2 * segments
    ranges_at = deltas_at + 2 * segments
    read = lambda at, kind: struct.unpack(">%d%s" % (segments, kind), data[at:at + 2 * segments])
    ends, starts = read(ends_at, "H"), read(starts_at, "H")
    deltas, ranges = read(deltas_at, "h"), read(ranges_at, "H")

    def glyph(code):
        for k in range(segments):
            if starts[k] <= code <= ends[k]:
                if ranges[k] == 0:
                    return (code + deltas[k]) & 0xFFFF
                where = ranges_at + 2 * k + ranges[k] + 2 * (code - starts[k])
                g = struct.unpack(">H", data[where:where + 2])[0]
                return (g + deltas[k]) & 0xFFFF if g else 0
        return 0
    return {c: advances[min(glyph(ord(c)), metrics - 1)] / units_per_em for c in chars}


def load_tool():
    import importlib.util
    spec = importlib.util.spec_from_file_location("render_mission", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class RenderTextFit(unittest.TestCase):
    """The panel's texts are fitted with a width estimate that must never fall short."""

    def font_file(self, pattern):
        if shutil.which("fc-match") is None:
            self.skipTest("fc-match (fontconfig) is not installed")
        path = subprocess.run(["fc-match", "-f", "%{file}", pattern], stdout=subprocess.PIPE,
                              timeout=30).stdout.decode()
        if "DejaVuSans" not in os.path.basename(path):
            self.skipTest("DejaVu Sans is not installed (fc-match gave %r)" % path)
        return path

    def test_estimate_is_an_upper_bound_of_dejavu_sans_widths(self):
        tool = load_tool()
        chars = [chr(c) for c in range(32, 127)] + ["\u2026"]
        for pattern, bold in (("DejaVu Sans", False), ("DejaVu Sans:bold", True)):
            widths = truetype_advance_widths_em(self.font_file(pattern), chars)
            self.assertGreater(widths["m"], widths["i"])   # the font was read
            short = [(c, round(em, 3)) for c, em in widths.items()
                     if tool.text_width_px(c, 1.0, bold) < em]
            self.assertEqual(short, [], pattern)

    def test_fitted_text_fits_or_is_cut_with_an_ellipsis(self):
        tool = load_tool()
        text, size = tool.fit_text("penalty 170410 (missed 154000, FA 16410, time 0)", 330, 12, 9)
        self.assertLessEqual(tool.text_width_px(text, size), 330)
        self.assertEqual(text, "penalty 170410 (missed 154000, FA 16410, time 0)")
        text, size = tool.fit_text("W" * 200, 330, 12, 9, bold=True)
        self.assertTrue(text.endswith("\u2026"))
        self.assertEqual(size, 9)
        self.assertLessEqual(tool.text_width_px(text, size, bold=True), 330)


if __name__ == "__main__":
    TOOL = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
