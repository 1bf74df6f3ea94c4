"""The .alog our logger writes (include/moos/alog.hpp, src/moos/alog.cpp), read as the C++
parse_alog_line reads it.

A file is header lines (their first non-blank characters are "%%"), blank lines and entries
TIME VARIABLE SOURCE VALUE. The fields are separated by blanks and tabs only; VALUE is the rest
of the line after the blanks that follow SOURCE (it may contain blanks; the logger writes a
newline inside a value as a blank, so one posting is one line). A trailing CR is ignored.
An entry is malformed when it has no SOURCE or when TIME is not a number (the base grammar).
A TIME that reads as a number but is not finite or lies beyond MAX_TIME_S (`nan`, `-inf`,
`1e300`: no clock wrote it) is unusable: the line is skipped and counted in AlogSkips, so a
reader warns once with the count, not once a line. A line over MAX_LINE_CHARS is skipped and
counted too: memory stays bounded whatever the log holds.

Speed: a reader asks for the variables it uses (`wanted`); the time of any other line is never
converted, so a large log costs one split per line.
"""

import re

from .text import parse_number

# TIME VARIABLE SOURCE VALUE, separated by blanks and tabs only.
ANY_ENTRY = re.compile(r"[ \t]*([^ \t]+)[ \t]+([^ \t]+)[ \t]+([^ \t]+)[ \t]*(.*)", re.S)
BLANKS = " \t"
MAX_TIME_S = 1e10          # as moos::kMaxAlogTimeS: above any epoch time and time since LOGSTART
MAX_LINE_CHARS = 1 << 20   # as the C++ readers' 1 MiB line bound


class AlogSkips:
    """Lines skipped without a warning each: counted, for one warning per kind at the end."""

    def __init__(self):
        self.unusable_times = 0
        self.long_lines = 0

    def warnings(self, path):
        """One line per kind of skipped line, naming the log (none when nothing was skipped)."""
        out = []
        if self.unusable_times:
            out.append("%s: %d line%s with unusable times (not finite, or beyond 1e10 s) skipped"
                       % (path, self.unusable_times, "" if self.unusable_times == 1 else "s"))
        if self.long_lines:
            out.append("%s: %d lines over %d characters skipped"
                       % (path, self.long_lines, MAX_LINE_CHARS))
        return out


def _reads_as_float(text):
    """A number as strtod reads it, perhaps not finite ('nan', '-inf', '1e999')."""
    if not text.isascii() or "_" in text:
        return False
    try:
        float(text)
    except ValueError:
        return False
    return True


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


def read_alog(path, wanted=None, on_malformed=None, header=None, skips=None):
    """The entries of the log at `path`, in file order, as an iterator of tuples
    (time_s, variable, source, value, line_no), line_no counting from 1.

    wanted(variable) -> bool selects the entries (None: all); on_malformed(line_no, reason) is
    called for each malformed line (a short line always, a bad time only on a wanted variable);
    header (an AlogHeader) is filled from the header lines; skips (an AlogSkips) counts the
    lines with unusable times (of wanted variables) and the lines over MAX_LINE_CHARS. Opening the file happens here, so an
    unreadable log raises OSError from this call, not from the iteration."""
    stream = open(path, encoding="utf-8", errors="replace", newline="\n")
    return _entries(stream, wanted, on_malformed, header, skips or AlogSkips())


def _bounded_lines(stream, skips):
    """(line_no, line) of the stream; a line over MAX_LINE_CHARS is read past, never held."""
    line_no = 0
    read = stream.readline
    while True:
        line = read(MAX_LINE_CHARS + 1)
        if not line:
            return
        line_no += 1
        if len(line) > MAX_LINE_CHARS and not line.endswith("\n"):
            skips.long_lines += 1
            while line and not line.endswith("\n"):
                line = read(MAX_LINE_CHARS)
            continue
        yield line_no, line


def _entries(stream, wanted, on_malformed, header, skips):
    with stream:
        for line_no, line in _bounded_lines(stream, skips):
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
            if time_s is None or abs(time_s) > MAX_TIME_S:
                if time_s is not None or _reads_as_float(time_text):
                    skips.unusable_times += 1
                elif on_malformed:
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
