#!/usr/bin/env python3
"""The picture's text-width estimate against the installed DejaVu Sans metrics (it must never
fall short), and text fitting (a smaller font, then an ellipsis).
"""

import os
import shutil
import subprocess
import sys
import unittest

from render_support import TOOLS


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
    """The module that estimates and fits texts (tools/mission_picture/text_fit.py)."""
    sys.path.insert(0, TOOLS)
    from mission_picture import text_fit
    return text_fit


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
    unittest.main(verbosity=2)
