"""missions/common/mission_summary.py --out naming each kind of output (a device, a full device,
a FIFO with and without a reader, a link, a regular file, a folder): the rule of
tools/mission_files/output_file.py, through the script itself."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCRIPT = os.path.join(REPO, "missions", "common", "mission_summary.py")
sys.path.insert(0, os.path.join(REPO, "tests", "tools", "mission_files"))
from output_targets import OutputTargetChecks  # noqa: E402

HAZARDS = "hazard = x=1,y=-1,label=h1,type=hazard\n"
ALOG = ("%% LOG FILE:       run.alog\n%% LOGSTART           1700000000.000\n%%%%%%%%\n"
        "5.000      DEPLOY_ALL           launch-1         true\n")
DEADLINE_S = 60


class SummaryOutputs(OutputTargetChecks, unittest.TestCase):
    NAME = "summary.json"

    @classmethod
    def setUpClass(cls):
        cls.inputs = tempfile.mkdtemp(prefix="summary_inputs_")
        for name, text in (("run.alog", ALOG), ("h.txt", HAZARDS)):
            with open(os.path.join(cls.inputs, name), "w") as f:
                f.write(text)

    @classmethod
    def tearDownClass(cls):
        for name in os.listdir(cls.inputs):
            os.unlink(os.path.join(cls.inputs, name))
        os.rmdir(cls.inputs)

    def write_to(self, path):
        r = subprocess.run([sys.executable, SCRIPT, "--alog", os.path.join(self.inputs, "run.alog"),
                            "--hazards", os.path.join(self.inputs, "h.txt"), "--out", path,
                            "--title", "T", "--mission", "m"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=DEADLINE_S)
        return r.returncode, r.stderr.decode(errors="replace")

    def check_bytes(self, data):
        summary = json.loads(data.decode())
        self.assertEqual(summary["title"], "T")
        self.assertEqual(summary["truth"], {"hazards": 1, "benign": 0})


if __name__ == "__main__":
    unittest.main(verbosity=2)
