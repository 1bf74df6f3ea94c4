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

import re

from .text import parse_number

# TIME VARIABLE SOURCE VALUE, separated by blanks and tabs only.
ANY_ENTRY = re.compile(r"[ \t]*([^ \t]+)[ \t]+([^ \t]+)[ \t]+([^ \t]+)[ \t]*(.*)", re.S)
BLANKS = " \t"


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
    """The entries of the log at `path`, in file order, as an iterator of tuples
    (time_s, variable, source, value, line_no), line_no counting from 1.

    wanted(variable) -> bool selects the entries (None: all); on_malformed(line_no, reason) is
    called for each malformed line (a short line always, a bad time only on a wanted variable);
    header (an AlogHeader) is filled from the header lines. Opening the file happens here, so an
    unreadable log raises OSError from this call, not from the iteration."""
    stream = open(path, encoding="utf-8", errors="replace", newline="\n")
    return _entries(stream, wanted, on_malformed, header)


def _entries(stream, wanted, on_malformed, header):
    with stream:
        for line_no, line in enumerate(stream, 1):
            line = line.rstrip("\n")
            if line[-1:] == "\r":
                line = line[:-1]
            if line.isascii() and line.isprintable():
                # Printable ASCII has no blank but the space: str.split splits as the C++
                # reader, at C speed (the other lines take the pattern).
                fields = line.split(None, 3)
                if len(fields) < 3 or fields[0].startswith("%%"):
                    _unusual_line(line, line_no, on_malformed, header)
                    continue
                if len(fields) == 3:
                    fields.append("")
            else:
                match = ANY_ENTRY.match(line)
                if match is None or match.group(1).startswith("%%"):
                    _unusual_line(line, line_no, on_malformed, header)
                    continue
                fields = match.groups()
            time_text, variable, source, value = fields
            if wanted is not None and not wanted(variable):
                continue
            time_s = parse_number(time_text)
            if time_s is None:
                if on_malformed:
                    on_malformed(line_no, "time '%s' is not a finite number" % time_text)
                continue
            yield time_s, variable, source, value, line_no   # a plain tuple: built at C speed


def _unusual_line(line, line_no, on_malformed, header):
    """A blank line, a header line (read into header) or a line without a SOURCE."""
    start = line.lstrip(BLANKS)
    if not start:
        return
    if start.startswith("%%"):
        if header is not None:
            header.read(start)
        return
    if on_malformed:
        on_malformed(line_no, "expected TIME VARIABLE SOURCE VALUE")
