#!/usr/bin/env python3
"""tools/mission_files/hazard_file.py reads a hazard file by the sensor's rules
(docs/hazard-file.md): keys in any case, values trimmed, a line rejected for a missing field,
a value that is not a finite number (nan included), a range or a duplicate label, hints
dropped; the warnings are the sensor's texts (the examples of docs/hazard-file.md)."""

import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))   # the package under test
from mission_files.hazard_file import parse_hazard_text, read_hazard_file  # noqa: E402

DOC_EXAMPLE = """// gen_hazards --polygon=-150,-75:-150,-400:400,-400:400,-75 --objects=5,hazard
source = jake survey
region = pts={-150,-75:-150,-400:400,-400:400,-75}
hazard = x=-52,y=-290,label=75,type=hazard
hazard = x=-41,y=-246,label=82,type=benign,hr=0.73
hazard = x=37,y=-207,label=99,type=benign,aspect=57,aspect_min=20,aspect_max=45
"""


def one(line):
    """(objects, warnings) of a file holding only `line` (as hazards.txt line 1)."""
    result = parse_hazard_text(line + "\n", "hazards.txt")
    return result.objects, result.warnings


class ReadHazardFile(unittest.TestCase):
    def test_the_documented_example(self):
        field = parse_hazard_text(DOC_EXAMPLE, "h.txt")
        self.assertEqual(field.warnings, [])
        self.assertEqual(field.source, "jake survey")
        self.assertEqual(field.region, [(-150, -75), (-150, -400), (400, -400), (400, -75)])
        self.assertEqual([(o["label"], o["type"], o["hazard"]) for o in field.objects],
                         [("75", "hazard", True), ("82", "benign", False), ("99", "benign", False)])
        self.assertEqual(field.objects[1]["hr"], 0.73)
        self.assertEqual((field.objects[2]["aspect"], field.objects[2]["aspect_min"],
                          field.objects[2]["aspect_max"]), (57, 20, 45))

    def test_keys_in_any_case_values_trimmed_comments_and_crlf(self):
        objects, warnings = one("  HAZARD =  X = 1 , Y=-2.5,LABEL= a b ,Type=BENIGN // note\r")
        self.assertEqual(warnings, [])
        self.assertEqual((objects[0]["x"], objects[0]["y"], objects[0]["label"],
                          objects[0]["type"]), (1.0, -2.5, "a b", "benign"))

    def test_hazard_true_is_the_originals_alternative_to_type(self):
        self.assertEqual(one("hazard = x=1,y=2,label=a,hazard=yes")[0][0]["type"], "hazard")
        self.assertEqual(one("hazard = x=1,y=2,label=a,hazard=false")[0][0]["type"], "benign")

    def test_the_documented_warnings(self):
        cases = {
            "hazard = x=1,y=2,type=hazard": "missing field 'label'; line rejected",
            "hazard = x=three,y=2,label=a,type=hazard":
                "field 'x' value 'three' is not a number; line rejected",
            "hazard = x=1,y=2,label=a,type=benign,hr=2":
                "field 'hr' value '2' is outside [0, 1]; line rejected",
            "hazard = x=1,y=2,label=a,type=benign,aspect=400,aspect_min=10,aspect_max=20":
                "field 'aspect' value '400' is outside [0, 360); line rejected",
            "hazard = x=1,y=2,label=a,type=inert":
                "field 'type' value 'inert' is neither 'hazard' nor 'benign'; line rejected",
        }
        for line, warning in cases.items():
            objects, warnings = one(line)
            self.assertEqual((objects, warnings), ([], ["hazards.txt:1: " + warning]), line)

    def test_nan_and_inf_are_not_positions(self):
        for value in ("nan", "inf", "-inf", "1e999"):
            objects, warnings = one("hazard = x=%s,y=2,label=a,type=hazard" % value)
            self.assertEqual(objects, [], value)
            self.assertEqual(warnings, ["hazards.txt:1: field 'x' value '%s' is not a number; "
                                        "line rejected" % value])

    def test_hints_dropped_and_unknown_keys_ignored_the_object_loads(self):
        objects, warnings = one("hazard = x=1,y=2,label=a,type=hazard,shape=blob,width=-1,"
                                "colour=red,x=3")
        self.assertEqual(len(objects), 1)
        self.assertEqual((objects[0]["x"], objects[0]["shape"], objects[0]["width"]),
                         (3.0, None, None))
        self.assertEqual(warnings, [
            "hazards.txt:1: field 'shape' value 'blob' is not a known shape; hint ignored",
            "hazards.txt:1: field 'width' value '-1' is not a number >= 0; hint ignored",
            "hazards.txt:1: unknown key 'colour' (value 'red') ignored",
            "hazards.txt:1: key 'x' repeated; the later value is used"])

    def test_warnings_are_bounded_per_line_and_per_file(self):
        # A line of 100,000 unknown keys: eight warnings and a count, as the sensor gives.
        keys = "".join(",k%d=1" % i for i in range(100000))
        objects, warnings = one("hazard = x=1,y=2,label=a,type=hazard" + keys)
        self.assertEqual(len(objects), 1)
        self.assertEqual(warnings, ["hazards.txt:1: unknown key 'k%d' (value '1') ignored" % i
                                    for i in range(8)] +
                         ["hazards.txt:1: ... and 99992 more warnings on this line"])
        # A file of 500 bad lines: 100 warnings and a count.
        field = parse_hazard_text("nonsense\n" * 500, "h.txt")
        self.assertEqual(len(field.warnings), 101)
        self.assertEqual(field.warnings[-1], "h.txt: ... and 400 more warnings")

    def test_aspect_windows(self):
        self.assertEqual(one("hazard = x=1,y=2,label=a,type=benign,aspect=10,aspect_min=30,"
                             "aspect_max=20")[1],
                         ["hazards.txt:1: aspect_min 30 is greater than aspect_max 20; "
                          "line rejected"])
        self.assertEqual(one("hazard = x=1,y=2,label=a,type=benign,aspect=10,aspect_min=45,"
                             "aspect_max=50")[1],
                         ["hazards.txt:1: aspect_min + aspect_max = 95 exceeds 90; line rejected"])
        objects, warnings = one("hazard = x=1,y=2,label=a,type=benign,aspect=10")
        self.assertEqual(len(objects), 1)
        self.assertIn("partial aspect data", warnings[0])

    def test_duplicate_labels_keep_the_first(self):
        field = parse_hazard_text("hazard = x=1,y=2,label=a,type=hazard\n"
                                  "hazard = x=5,y=6,label=a,type=benign\n", "hazards.txt")
        self.assertEqual([(o["x"], o["type"]) for o in field.objects], [(1.0, "hazard")])
        self.assertEqual(field.warnings, ["hazards.txt:2: duplicate label 'a'; the first object "
                                          "with this label is kept, this line is rejected"])

    def test_lat_lon_only_and_unrecognised_lines(self):
        objects, warnings = one("hazard = lat=42.3,lon=-71.1,label=a,type=hazard")
        self.assertEqual(objects, [])
        self.assertIn("position given only as lat/lon cannot be placed", warnings[0])
        self.assertEqual(one("colour = red")[1],
                         ["hazards.txt:1: unrecognised line 'colour = red' ignored (expected "
                          "'hazard = ...', 'region = ...' or 'source = ...')"])

    def test_files(self):
        folder = tempfile.mkdtemp(prefix="hazard_file_test_")
        try:
            path = os.path.join(folder, "h.txt")
            with open(path, "w") as f:
                f.write(DOC_EXAMPLE)
            self.assertEqual(len(read_hazard_file(path).objects), 3)
            with open(path, "w") as f:
                f.write("")
            self.assertEqual(read_hazard_file(path).objects, [])
            with self.assertRaises(OSError):
                read_hazard_file(os.path.join(folder, "missing.txt"))
        finally:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    unittest.main(verbosity=2)
