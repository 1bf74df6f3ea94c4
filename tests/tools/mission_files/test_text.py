#!/usr/bin/env python3
"""tools/mission_files/text.py: the base grammar of include/base/text.hpp in Python. Numbers are
what base::parse_number accepts and nothing else (nan, inf and overflow are not numbers),
trimming removes blanks, tabs, CR and LF only, `key=value` lists split as
base::split_key_values."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))   # the package under test
from mission_files.text import (  # noqa: E402
    excerpt, json_number, key_values, parse_bool, parse_number, parse_points, split_key_values,
    to_lower, trim)


class Numbers(unittest.TestCase):
    def test_the_grammar_of_base_parse_number(self):
        accepted = {"0": 0.0, "-3": -3.0, "+2.5": 2.5, ".5": 0.5, "5.": 5.0, "1e3": 1000.0,
                    "1E-2": 0.01, " \t12\r\n": 12.0, "-0.0": 0.0, "1e-400": 0.0}
        for text, value in accepted.items():
            self.assertEqual(parse_number(text), value, repr(text))

    def test_non_finite_numbers_are_rejected(self):
        for text in ("nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-1e400"):
            self.assertIsNone(parse_number(text), text)

    def test_what_python_reads_but_the_grammar_does_not(self):
        for text in ("1_000", "0x10", "", " ", ".", "-", "e5", "1e", "1e+", "1.2.3", "12a",
                     "\u0661", "\x0b1", "1 2", None):
            self.assertIsNone(parse_number(text), repr(text))

    def test_json_numbers_keep_whole_numbers_whole(self):
        self.assertEqual(repr(json_number("25")), "25")
        self.assertEqual(repr(json_number(" +7 ")), "7")
        self.assertEqual(repr(json_number("0.656")), "0.656")
        self.assertEqual(repr(json_number("1e3")), "1000.0")
        for text in ("nan", "inf", "abc", None, "1" * 400):
            self.assertIsNone(json_number(text), text)


class Words(unittest.TestCase):
    def test_booleans(self):
        for text in ("true", "YES", " On "):
            self.assertIs(parse_bool(text), True)
        for text in ("false", "No", "OFF"):
            self.assertIs(parse_bool(text), False)
        for text in ("toggle", "1", ""):
            self.assertIsNone(parse_bool(text))

    def test_trim_removes_blanks_tabs_cr_and_lf_only(self):
        self.assertEqual(trim(" \t a b \r\n"), "a b")
        self.assertEqual(trim("\x0ba\x0c"), "\x0ba\x0c")

    def test_lower_case_is_ascii_only(self):
        self.assertEqual(to_lower("NAME"), "name")
        self.assertEqual(to_lower("\u00c9X"), "\u00c9x")

    def test_excerpt_cuts_long_texts_and_says_how_long(self):
        self.assertEqual(excerpt("short"), "short")
        self.assertEqual(excerpt("x" * 200), "x" * 160 + " ... (200 bytes)")


class KeyValues(unittest.TestCase):
    def test_split_like_base_split_key_values(self):
        self.assertEqual(split_key_values(" a = 1 ,, b=x=y ,c "),
                         [("a", "1", True), ("b", "x=y", True), ("c", "", False)])

    def test_braces_keep_their_commas_when_asked(self):
        self.assertEqual(split_key_values("pts={1,2:3,4},x=1", respect_braces=True),
                         [("pts", "{1,2:3,4}", True), ("x", "1", True)])
        self.assertEqual(len(split_key_values("pts={1,2:3,4},x=1")), 4)   # pts={1 2:3 4} x=1

    def test_key_values_lower_case_keys_and_later_wins(self):
        self.assertEqual(key_values("NAME=ann, X = 1 ,x=2,junk,pts={0,0:1,1}"),
                         {"name": "ann", "x": "2", "pts": "{0,0:1,1}"})

    def test_points(self):
        self.assertEqual(parse_points("pts={0,0:10,-5}"), [(0.0, 0.0), (10.0, -5.0)])
        self.assertEqual(parse_points("label=r, pts = {1,2:3,4}"), [(1.0, 2.0), (3.0, 4.0)])
        self.assertEqual(parse_points("1,2:3,4"), [(1.0, 2.0), (3.0, 4.0)])
        self.assertIsNone(parse_points("pts={0,0:nan,1}"))
        self.assertIsNone(parse_points("pts={0,0:1}"))


if __name__ == "__main__":
    unittest.main(verbosity=2)
