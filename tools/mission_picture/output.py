"""Writing the picture: the SVG file, and the PNG through rsvg-convert when it is installed. Both
are user-named outputs, written by mission_files.output_file's rule (a regular file replaced
atomically, a device or FIFO written through, a link kept): rsvg-convert writes the PNG to a
pipe, never to the named file itself."""

import os
import shutil
import subprocess

from mission_files.output_file import write_output_file

from .layout import CANVAS_H, CANVAS_W
from .run_log import warn

PNG_TIMEOUT_S = 120


def write_svg(svg, path):
    """True when the SVG text was written to path (else a warning names the problem)."""
    try:
        write_output_file(path, svg)
    except OSError as e:
        warn(str(e))
        return False
    return True


def write_png(svg, svg_path, png_path=None):
    """The SVG text converted to png_path (default: the SVG's name with .png); True unless the
    converter failed or the PNG cannot be written. Without rsvg-convert a warning says no PNG
    was written. The SVG goes to the converter on its standard input, so an SVG written to a
    device or a FIFO converts as well."""
    png = png_path or os.path.splitext(svg_path)[0] + ".png"
    converter = shutil.which("rsvg-convert")
    if not converter:
        warn("rsvg-convert not found (Debian package librsvg2-bin): no PNG written")
        return True
    command = [converter, "-w", str(CANVAS_W), "-h", str(CANVAS_H)]
    result = subprocess.run(command, input=svg.encode("utf-8"), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, timeout=PNG_TIMEOUT_S)
    if result.returncode != 0:
        warn("rsvg-convert failed: %s" % result.stderr.decode(errors="replace").strip())
        return False
    try:
        write_output_file(png, result.stdout)
    except OSError as e:
        warn(str(e))
        return False
    return True
