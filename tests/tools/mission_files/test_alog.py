#!/usr/bin/env python3
"""tools/mission_files/alog.py reads an .alog as moos::parse_alog_line does (src/moos/alog.cpp):
fields separated by blanks and tabs only, VALUE the rest of the line, a trailing CR ignored,
header lines from "%%", a time that is not a number malformed and one that is not finite or
beyond 1e10 s (nan, inf, 1e300) unusable: skipped and counted, for one warning; the variables not
asked for are skipped before their time is read; a line over MAX_LINE_CHARS is skipped, counted."""

import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))   # the package under test
from mission_files import alog  # noqa: E402
from mission_files.alog import AlogHeader, AlogSkips, read_alog  # noqa: E402

# Lines as format_alog_line writes them: time %.3f padded to 10, variable to 20, source to 16.
LOG = ("%% LOG FILE:       run.alog\n"
       "%% LOGSTART           1700000000.250\n"
       "%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%\n"
       "1.000      DEPLOY_ALL           launch           true\n"
       "\n"
       "2.500      NOTE                 pLogLite         a value  with  blanks \r\n"
       "3.000\tTABBED\tsrc\tx=1,\ty=2\n"
       "nan        NODE_REPORT          sim              NAME=a,X=1,Y=1\n"
       "inf        NODE_REPORT          sim              NAME=a,X=1,Y=1\n"
       "4.000      SHORT\n"
       "5.000      EMPTY_VALUE          src\n"
       "6.000\x0cFORM_FEED src value\n"
       "   %% an indented header line\n"
       "7.000      LAST                 src              =\r\n")


class ReadAlog(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="alog_test_")
        self.path = os.path.join(self.dir, "run.alog")
        with open(self.path, "w", newline="") as f:
            f.write(LOG)
        self.malformed = []
        self.skips = AlogSkips()

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def read(self, wanted=None, header=None):
        return list(read_alog(self.path, wanted, lambda n, why: self.malformed.append((n, why)),
                              header, self.skips))

    def test_entries_as_the_cpp_parser_reads_them(self):
        entries = {e[1]: e for e in self.read()}
        self.assertEqual(sorted(entries), ["DEPLOY_ALL", "EMPTY_VALUE", "LAST", "NOTE", "TABBED"])
        note = entries["NOTE"]
        self.assertEqual((note[0], note[2], note[3], note[4]),
                         (2.5, "pLogLite", "a value  with  blanks ", 6))
        self.assertEqual(entries["TABBED"][3], "x=1,\ty=2")
        self.assertEqual(entries["EMPTY_VALUE"][3], "")
        self.assertEqual(entries["LAST"][3], "=")

    def test_short_lines_are_malformed_and_nan_and_inf_times_counted(self):
        self.read()
        self.assertEqual([n for n, _why in self.malformed], [10, 12])
        self.assertEqual(self.malformed[0][1], "expected TIME VARIABLE SOURCE VALUE")
        self.assertEqual(self.skips.unusable_times, 2)

    def test_unusable_times_are_skipped_with_one_warning(self):
        with open(self.path, "w") as f:
            f.write("1.0 A src v\nnan A src v\n-inf A src v\n1e300 A src v\n-1e300 A src v\n"
                    "1e999 A src v\n2.0 A src w\n%% 10 lines dropped\n")
        entries = self.read()
        self.assertEqual([(e[0], e[3]) for e in entries], [(1.0, "v"), (2.0, "w")])
        self.assertEqual(self.malformed, [])
        self.assertEqual(self.skips.warnings("run.alog"),
                         ["run.alog: 5 lines with unusable times (not finite, or beyond 1e10 s) "
                          "skipped"])

    def test_a_line_over_the_bound_is_skipped_and_counted(self):
        with open(self.path, "w") as f:
            f.write("1.0 A src v\n2.0 B src " + "k=1," * (alog.MAX_LINE_CHARS // 4 + 10) +
                    "\n3.0 C src w\n")
        entries = self.read()
        self.assertEqual([(e[1], e[4]) for e in entries], [("A", 1), ("C", 3)])
        self.assertEqual(self.skips.long_lines, 1)
        self.assertIn("1 lines over", self.skips.warnings("run.alog")[0])

    def test_a_form_feed_is_not_a_separator(self):
        self.read()
        self.assertIn((12, "time '6.000\x0cFORM_FEED' is not a finite number"), self.malformed)

    def test_unwanted_variables_are_skipped_before_their_time_is_read(self):
        entries = self.read(wanted=lambda v: v == "DEPLOY_ALL")
        self.assertEqual([e[1] for e in entries], ["DEPLOY_ALL"])
        self.assertEqual([n for n, _why in self.malformed], [10])   # only the short line

    def test_header(self):
        header = AlogHeader()
        self.read(header=header)
        self.assertEqual((header.log_name, header.logstart_s), ("run.alog", 1700000000.25))

    def test_an_unreadable_log_fails_at_the_call(self):
        with self.assertRaises(OSError):
            read_alog(os.path.join(self.dir, "missing.alog"))

    def test_bytes_that_are_not_utf8_are_replaced(self):
        with open(self.path, "wb") as f:
            f.write(b"1.0 VAR src caf\xe9\n")
        self.assertEqual(self.read()[0][3], "caf\ufffd")


if __name__ == "__main__":
    unittest.main(verbosity=2)
