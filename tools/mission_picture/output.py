"""Writing the picture: the SVG file, and the PNG through rsvg-convert when it is installed."""

import os
import shutil
import subprocess

from .layout import CANVAS_H, CANVAS_W
from .run_log import warn

PNG_TIMEOUT_S = 120


def write_svg(svg, path):
    """True when the SVG text was written to path (else a warning names the problem)."""
    try:
        with open(path, "w", encoding="utf-8") as f:
            f.write(svg)
    except OSError as e:
        warn("cannot write %s: %s" % (path, e))
        return False
    return True


def write_png(svg_path, png_path=None):
    """The SVG converted to png_path (default: the SVG's name with .png); True unless the
    converter failed. Without rsvg-convert a warning says no PNG was written."""
    png = png_path or os.path.splitext(svg_path)[0] + ".png"
    converter = shutil.which("rsvg-convert")
    if not converter:
        warn("rsvg-convert not found (Debian package librsvg2-bin): no PNG written")
        return True
    command = [converter, "-w", str(CANVAS_W), "-h", str(CANVAS_H), "-o", png, svg_path]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            timeout=PNG_TIMEOUT_S)
    if result.returncode != 0:
        warn("rsvg-convert failed: %s" % result.stderr.decode(errors="replace").strip())
        return False
    return True
