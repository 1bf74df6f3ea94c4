#!/usr/bin/env python3
"""tools/mission_files/run_files.py (summary.json, cpu.txt) and messages.py (HAZARDSET_REPORT,
HAZARD_HANDOVER values)."""

import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))   # the package under test
from mission_files.messages import hazard_handover, hazardset_report  # noqa: E402
from mission_files.run_files import read_cpu, read_summary, summary_evals  # noqa: E402


class RunFiles(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="run_files_test_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_summary_evals_in_every_form_as_text(self):
        self.assertEqual(summary_evals({"evals": [{"vname": "a", "Norm_Score": 91.5}]}),
                         [{"vname": "a", "norm_score": "91.5"}])
        self.assertEqual(summary_evals({"scores": ["vname=b, norm_score=80", 7]}),
                         [{"vname": "b", "norm_score": "80"}, {}])
        self.assertEqual(summary_evals({"evals": {"c": {"norm_score": 1}}}),
                         [{"norm_score": "1", "vname": "c"}])
        self.assertEqual(summary_evals({"evals": "not a list"}), [])

    def test_read_summary_needs_a_json_object(self):
        self.assertEqual(read_summary(self.write("s.json", '{"title": "T"}')), {"title": "T"})
        with self.assertRaises(ValueError):
            read_summary(self.write("list.json", "[1, 2]"))
        with self.assertRaises(ValueError):
            read_summary(self.write("bad.json", "{"))
        with self.assertRaises(OSError):
            read_summary(os.path.join(self.dir, "missing.json"))

    def test_cpu_lines_of_a_name_and_two_numbers(self):
        path = self.write("cpu.txt", "moosdb-lite 0.50 1.25\nsensor 1 2\nbroken line\n"
                                     "nan_user nan 1\nthree parts here\n")
        self.assertEqual(read_cpu(path), [
            {"name": "moosdb-lite", "cpu_user_s": 0.5, "cpu_system_s": 1.25},
            {"name": "sensor", "cpu_user_s": 1, "cpu_system_s": 2}])
        self.assertEqual(read_cpu(os.path.join(self.dir, "missing.txt")), [])


class Messages(unittest.TestCase):
    def test_hazardset_report(self):
        self.assertEqual(hazardset_report("source=betty#name=betty#x=1,y=2,label=h1#"
                                          "x=3,y=4,label= b2 #x=5,y=6,label="),
                         ("betty", ["h1", "b2"]))
        self.assertEqual(hazardset_report("#x=1,y=2,label=3"), ("", ["3"]))

    def test_hazard_handover(self):
        self.assertEqual(hazard_handover("source=a#dest=b#prior=0.5#label=1,x=0,y=0#label=2"),
                         ({"source": "a", "dest": "b", "prior": "0.5"}, 2))
        self.assertEqual(hazard_handover("garbage"), ({}, 0))


if __name__ == "__main__":
    unittest.main(verbosity=2)
