"""tools/render_mission.py's user-named outputs, --svg and --png, naming each kind of output (a
device, a full device, a FIFO with and without a reader, a link, a regular file, a folder): the
rule of tools/mission_files/output_file.py, through the tool itself. The PNG cases need
rsvg-convert (skipped without it)."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "mission_files"))
import render_support  # noqa: E402  (beside this file)
from output_targets import OutputTargetChecks  # noqa: E402

DEADLINE_S = 100


class InputsOnce:
    @classmethod
    def setUpClass(cls):
        cls.inputs = tempfile.mkdtemp(prefix="render_inputs_")
        for name, text in (("run.alog", render_support.ALOG), ("h.txt", render_support.HAZARDS)):
            with open(os.path.join(cls.inputs, name), "w") as f:
                f.write(text)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.inputs, ignore_errors=True)

    def render(self, extra):
        command = [sys.executable, render_support.TOOL, "--alog", os.path.join(self.inputs, "run.alog"),
                   "--hazards", os.path.join(self.inputs, "h.txt"), *extra]
        r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=DEADLINE_S)
        return r.returncode, r.stderr.decode(errors="replace")


class RenderSvgOutputs(InputsOnce, OutputTargetChecks, unittest.TestCase):
    NAME = "mission.svg"

    def write_to(self, path):
        return self.render(["--svg", path, "--no-png"])

    def check_bytes(self, data):
        self.assertTrue(data.startswith(b"<svg") or data.startswith(b"<?xml"), data[:80])
        self.assertTrue(data.rstrip().endswith(b"</svg>"))


@unittest.skipUnless(shutil.which("rsvg-convert"), "rsvg-convert is not installed")
class RenderPngOutputs(InputsOnce, OutputTargetChecks, unittest.TestCase):
    NAME = "mission.png"

    def write_to(self, path):
        # The SVG goes to a plain file beside it: only the PNG is the output under test.
        return self.render(["--svg", os.path.join(self.dir, "mission.svg"), "--png", path])

    def check_bytes(self, data):
        self.assertTrue(data.startswith(b"\x89PNG\r\n\x1a\n"), data[:16])


if __name__ == "__main__":
    unittest.main(verbosity=2)
