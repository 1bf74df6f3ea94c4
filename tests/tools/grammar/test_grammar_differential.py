#!/usr/bin/env python3
"""The Python tools' number grammar and hazard-file loader (tools/mission_files/text.py,
hazard_file.py) held to the C++ ones (base::parse_number, hazard::load_hazard_file_text):
a generated and an edge-case corpus goes to both, through grammar_probe (this folder), and
every verdict, value (bit for bit), object and warning text must be the same.

Not compared: `region =` lines (the sensor skips them; the tools read the polygon and warn of a
bad one), the `source =` line's text (the same), and colour words outside the known colours
(the sensor refuses them with a warning, the tools keep them as written for the picture). GRAMMAR_PROBE names the program (ctest sets
it)."""

import os
import random
import struct
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))   # the package under test
from mission_files.hazard_file import parse_hazard_text  # noqa: E402
from mission_files.text import parse_number  # noqa: E402

PROBE = os.environ.get("GRAMMAR_PROBE", "")

EDGE_NUMBERS = [
    "0", "-0", "+0", "-0.0", "0e0", "-0e-5", "1.7976931348623157e308", "1.7976931348623159e308",
    "1e308", "1e309", "4.9406564584124654e-324", "2.4703282292062327e-324",
    "2.4703282292062328e-324", "1e-320", "1e-400", "-1e-400", "2.2250738585072011e-308",
    "9007199254740993", "0.1000000000000000055511151231257827", "+.5", "5.", ".5e1", "+5.e-1",
    "00000000000000000000000001", "1e0000000000000000000000002", ".", "+", "-", "e1", "1e", "1e+",
    "--1", "+-1", "-+1", "1..2", "0x1p3", "0x10", "inf", "-inf", "+inf", "nan", "NaN", "infinity",
    "1 2", "", " ", "\t1\r\n", " 1", "1_000", "1\u00a0", "\u0661", "１", "1.5f", "1d", "1e5.5",
    ".e1", "-.5", "+.", "5e-", "0." + "0" * 800 + "1e790", "9" * 400, "1\x00", "\x0b1", "\x0c1",
    "1e99999999999999999999", "1e-99999999999999999999", "0e999999",
]


def number_like(rng):
    """Texts near and off the grammar: signs, long mantissas, exponents past both ends."""
    def digits(n):
        return "".join(rng.choice("0123456789") for _ in range(rng.randint(0, n)))
    out = rng.choice(["", "", "", " ", "\t"])
    out += rng.choice(["", "", "-", "+"])
    out += digits(40 if rng.random() < 0.1 else 12)
    if rng.random() < 0.5:
        out += "." + digits(40 if rng.random() < 0.1 else 12)
    if rng.random() < 0.5:
        out += rng.choice("eE") + rng.choice(["", "-", "+"]) + str(rng.randint(0, 420))
    if rng.random() < 0.1:
        at = rng.randint(0, len(out))
        out = out[:at] + rng.choice("+-.eEx n_\x00\u00a0") + out[at:]
    return out + rng.choice(["", "", "", " ", "\r\n"])


def run_probe(args, data):
    done = subprocess.run([PROBE] + args, input=data, stdout=subprocess.PIPE, check=True)
    return done.stdout.decode("ascii").split("\n")[:-1]


def bits(value):
    return "-" if value is None else "%016x" % struct.unpack("<Q", struct.pack("<d", value))[0]


def hex_text(text):
    return "-" if text is None else (text.encode("utf-8").hex() or "=")


@unittest.skipUnless(PROBE, "GRAMMAR_PROBE is not set (run through ctest)")
class NumberGrammar(unittest.TestCase):
    def test_every_text_reads_as_the_cpp_parser_reads_it(self):
        rng = random.Random(14)
        texts = EDGE_NUMBERS + [number_like(rng) for _ in range(100000)]
        lines = "".join((t.encode("utf-8").hex() or "=") + "\n" for t in texts)
        got = run_probe(["numbers"], lines.encode("ascii"))
        self.assertEqual(len(got), len(texts))
        differ = [(t, want, bits(parse_number(t))) for t, want in zip(texts, got)
                  if bits(parse_number(t)) != want]
        self.assertEqual(differ[:10], [], "%d texts differ (text, C++, Python)" % len(differ))


VALUES = ["1", "-2.5", "1e2", "nan", "inf", "", " 3 ", "0x1", "1e999", "0.73", "1.5", "-0",
          "360", "359.99", "90", "45", "20", "-1", "abc", "1e-400", "+.5", "5.", "1..2", "7\t",
          "2e8", "-1.5e8"]
KEYS = ["x", "y", "X", "label", "type", "hr", "aspect", "aspect_min", "aspect_max", "width",
        "color", "shape", "source", "hazard", "lat", "lon", "colour", "Label"]
COLOURS = ["red", "light_blue", "green", "gray50"]   # the tools keep colour words unchecked
WORDS = ["hazard", "benign", "Hazard", "BENIGN", "rock", "true", "off", "circle", "efield",
         "blob", "red", "a b", "x\\y", "", "lbl"]


def hazard_line(rng, n):
    """A `hazard =` line of random pieces, mostly near-valid."""
    pieces = ["x=%s" % rng.choice(VALUES[:3] + VALUES), "y=%s" % rng.choice(VALUES),
              "label=%s" % rng.choice(["L%d" % n, "L%d" % rng.randint(0, 50), ""]),
              "type=%s" % rng.choice(WORDS[:4] + WORDS)]
    for _ in range(rng.randint(0, 4)):
        key = rng.choice(KEYS)
        value = rng.choice(COLOURS if key == "color" else VALUES + WORDS)
        pieces.append("%s=%s" % (key, value))
    if rng.random() < 0.05:
        pieces.append(rng.choice(["noequals", "", " "]))
    rng.shuffle(pieces)
    drop = rng.random()
    if drop < 0.15:
        pieces.pop(rng.randrange(len(pieces)))
    head = rng.choice(["hazard = ", "hazard=", "HAZARD = ", " hazard =  "])
    tail = rng.choice(["", "", " // note", "\r"])
    return head + rng.choice([",", ", "]).join(pieces) + tail


def hazard_file(rng, n):
    lines = []
    for i in range(n):
        r = rng.random()
        if r < 0.85:
            lines.append(hazard_line(rng, i))
        elif r < 0.9:
            lines.append(rng.choice(["", "// comment", "   ", "source = jake"]))
        else:
            lines.append(rng.choice(["bogus line", "hazards = x=1", "x=1,y=2", "=", "hazard"]))
    return "\n".join(lines) + "\n"


def python_view(text, name):
    field = parse_hazard_text(text, name)
    objects = ["O %s %s %s %s %s %s %s %s %s %s %s %s" % (
        hex_text(o["label"]), bits(o["x"]), bits(o["y"]), o["type"], bits(o["hr"]),
        bits(o["aspect"]), bits(o["aspect_min"]), bits(o["aspect_max"]), bits(o["width"]),
        hex_text(o["color"]), hex_text(o["shape"]), hex_text(o["source"]))
        for o in field.objects]
    warnings = ["W " + hex_text(w) for w in field.warnings if "bad region" not in w]
    return objects + warnings


@unittest.skipUnless(PROBE, "GRAMMAR_PROBE is not set (run through ctest)")
class HazardFileLoader(unittest.TestCase):
    def compare(self, text):
        got = run_probe(["hazards", "h.txt"], text.encode("utf-8"))
        want = python_view(text, "h.txt")
        for i, (c, p) in enumerate(zip(got, want)):
            if c != p:
                self.fail("line %d of the views differs:\nC++:    %s\nPython: %s" % (
                    i, bytes.fromhex(c[2:].split(" ")[0]) if c.startswith("W") else c,
                    bytes.fromhex(p[2:].split(" ")[0]) if p.startswith("W") else p))
        self.assertEqual(len(got), len(want))

    def test_generated_files_load_as_the_sensor_loads_them(self):
        rng = random.Random(27)
        for _ in range(60):
            self.compare(hazard_file(rng, rng.randint(1, 60)))

    def test_one_big_file_bounds_its_warnings_as_the_sensor_does(self):
        self.compare(hazard_file(random.Random(28), 3000))

    def test_edge_lines_load_as_the_sensor_loads_them(self):
        for line in ["hazard = x=1,y=2,label=a,type=hazard,lat=1,lon=2",
                     "hazard = lat=1,lon=2,label=a,type=hazard",
                     "hazard = x=1,y=2,label=a,hazard=true",
                     "hazard = x=1,y=2,label=a,type=benign,aspect=10,aspect_min=50,aspect_max=45",
                     "hazard = x=1,y=2,label=a,type=benign,aspect=10,aspect_min=50,aspect_max=41",
                     "hazard = x=1,y=2,label=a,type=benign,aspect=10",
                     "hazard = x=1,y=2,label=a,type=benign,x=3",
                     "hazard = x=1,y=2,label=a\\b,type=benign,zz=\\",
                     "hazard = x=1,y=2,label=a,type=benign,zz=" + "v" * 300,
                     "hazard = x=1,y=2,label=a\x01b,type=benign",
                     "hazard = x=1,y=2,label=" + "l" * 300 + ",type=benign",
                     "hazard = x=1e9,y=2,label=a,type=benign",
                     "\ufeffhazard = x=1,y=2,label=a,type=benign",
                     "hazard = " + ",".join("k%d=1" % i for i in range(100)),
                     "region = pts={1,2:3,4}", "source = s"]:
            with self.subTest(line=line):
                self.compare(line + "\n")


if __name__ == "__main__":
    unittest.main()
