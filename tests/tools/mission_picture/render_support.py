"""What the picture tool's tests share: the tool's path, a small hand-written run, running the
tool, and the structural checks of the large-field tests (frame, text extents).

The tool is tools/render_mission.py of this checkout (found from this file's place), run with
the Python that runs the tests.
"""

import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import synthetic_field  # noqa: E402  (beside this file)

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
TOOLS = os.path.join(REPO, "tools")
TOOL = os.path.join(TOOLS, "render_mission.py")

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


