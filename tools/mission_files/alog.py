"""The .alog our logger writes (include/moos/alog.hpp, src/moos/alog.cpp), read as the C++
parse_alog_line reads it.

A file is header lines (their first non-blank characters are "%%"), blank lines and entries
TIME VARIABLE SOURCE VALUE. The fields are separated by blanks and tabs only; VALUE is the rest
of the line after the blanks that follow SOURCE (it may contain blanks; the logger writes a
newline inside a value as a blank, so one posting is one line). A trailing CR is ignored.
An entry is malformed when it has no SOURCE or when TIME is not a finite number (the base
grammar: `nan` and `inf` are not times).

Speed: a reader asks for the variables it uses (`wanted`); the time of any other line is never
converted, so a large log costs one split per line.
"""

import collections
import re

from .text import parse_number

ENTRY_FIELDS = re.compile(r"[ \t]*([^ \t]+)[ \t]+([^ \t]+)[ \t]+([^ \t]+)[ \t]*(.*)", re.S)
BLANKS = " \t"

AlogEntry = collections.namedtuple("AlogEntry", "time_s variable source value line_no")
AlogEntry.__doc__ = "One posting of the log; line_no counts from 1."


class AlogHeader:
    """What the header lines say: `%% LOG FILE: <name>` and `%% LOGSTART <epoch seconds>`."""

    def __init__(self):
        self.log_name = None
        self.logstart_s = None

    def read(self, line):
        if "LOG FILE:" in line:
            name = line.split("LOG FILE:", 1)[1].split()
            if name:
                self.log_name = name[0]
        tokens = line.split()
        if tokens[:2] == ["%%", "LOGSTART"] and len(tokens) > 2:
            self.logstart_s = parse_number(tokens[2])


def read_alog(path, wanted=None, on_malformed=None, header=None):
    """The entries of the log at `path`, in file order, as an iterator of AlogEntry.

    wanted(variable) -> bool selects the entries (None: all); on_malformed(line_no, reason) is
    called for each malformed line (a short line always, a bad time only on a wanted variable);
    header (an AlogHeader) is filled from the header lines. Opening the file happens here, so an
    unreadable log raises OSError from this call, not from the iteration."""
    stream = open(path, encoding="utf-8", errors="replace", newline="\n")
    return _entries(stream, wanted, on_malformed, header)


def _entries(stream, wanted, on_malformed, header):
    with stream:
        for line_no, line in enumerate(stream, 1):
            if line.endswith("\n"):
                line = line[:-1]
            if line.endswith("\r"):
                line = line[:-1]
            start = line.lstrip(BLANKS)
            if not start:
                continue
            if start.startswith("%%"):
                if header is not None:
                    header.read(start)
                continue
            fields = ENTRY_FIELDS.match(line)
            if fields is None:
                if on_malformed:
                    on_malformed(line_no, "expected TIME VARIABLE SOURCE VALUE")
                continue
            time_text, variable, source, value = fields.groups()
            if wanted is not None and not wanted(variable):
                continue
            time_s = parse_number(time_text)
            if time_s is None:
                if on_malformed:
                    on_malformed(line_no, "time '%s' is not a finite number" % time_text)
                continue
            yield AlogEntry(time_s, variable, source, value, line_no)
