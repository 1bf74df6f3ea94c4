"""The instruction-count gate gates (bench/perf/gate.py, docs/performance.md): against a
baseline it just recorded it passes; against one lowered below the tolerance it exits 1 and
names the failing workload. Runs the smallest workload (gate-selftest) under valgrind.

PERF_WORKLOADS is the perf_workloads program (set by CTest)."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
GATE = os.path.join(HERE, "..", "..", "bench", "perf", "gate.py")
PROGRAM = os.environ.get("PERF_WORKLOADS", "")
WORKLOAD = "gate-selftest"


def gate(*args):
    return subprocess.run([sys.executable, GATE, "--program=" + PROGRAM, "--workloads=" + WORKLOAD] + list(args),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)


@unittest.skipIf(shutil.which("valgrind") is None, "valgrind is not installed: the gate cannot be tested")
class GateGates(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not os.access(PROGRAM, os.X_OK):
            raise unittest.SkipTest("PERF_WORKLOADS does not name a built perf_workloads")
        cls.folder = tempfile.mkdtemp(prefix="perf_gate_test.")
        cls.baseline = os.path.join(cls.folder, "baseline.json")
        result = gate("--baseline=" + cls.baseline, "--update", "--tolerance=2")
        if result.returncode != 0:
            raise AssertionError("gate.py --update failed: %s%s" % (result.stdout, result.stderr))
        with open(cls.baseline, encoding="utf-8") as f:
            cls.recorded = json.load(f)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)

    def write(self, name, instructions):
        baseline = json.loads(json.dumps(self.recorded))
        baseline["workloads"][WORKLOAD]["instructions"] = instructions
        path = os.path.join(self.folder, name)
        with open(path, "w", encoding="utf-8") as f:
            json.dump(baseline, f)
        return path

    def test_the_recorded_baseline_passes(self):
        result = gate("--baseline=" + self.baseline)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("instruction-count gate: passed", result.stdout)
        row = next(l for l in result.stdout.splitlines() if l.startswith(WORKLOAD))
        self.assertTrue(row.endswith("ok"), row)

    def test_a_lowered_baseline_fails_with_its_row(self):
        recorded = self.recorded["workloads"][WORKLOAD]["instructions"]
        lowered = self.write("lowered.json", int(recorded / 1.05))  # now is 5 % above it
        result = gate("--baseline=" + lowered)
        self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
        row = next(l for l in result.stdout.splitlines() if l.startswith(WORKLOAD))
        self.assertIn("FAIL", row)
        # About +5 %: mimalloc moves a count by a few thousandths of a percent run to run.
        change = float(row.split("%")[0].split()[-1])
        self.assertAlmostEqual(change, 5.0, delta=0.05, msg=row)
        self.assertIn("instruction-count gate: FAILED", result.stdout)

    def test_growth_within_the_tolerance_passes(self):
        recorded = self.recorded["workloads"][WORKLOAD]["instructions"]
        result = gate("--baseline=" + self.write("within.json", int(recorded / 1.01)))
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)

    def test_a_baseline_it_cannot_read_is_exit_status_2(self):
        path = os.path.join(self.folder, "broken.json")
        with open(path, "w", encoding="utf-8") as f:
            f.write("{\"workloads\": {\"gate-selftest\": {\"instructions\": -1}}}")
        result = gate("--baseline=" + path)
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertIn("gate.py:", result.stderr)


if __name__ == "__main__":
    unittest.main()
