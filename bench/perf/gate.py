#!/usr/bin/env python3
"""The instruction-count gate (docs/performance.md, "The instruction-count gate").

Runs each workload of perf_workloads under `valgrind --tool=cachegrind --cache-sim=no`, reads
the instructions executed (Ir), compares them with the committed baseline and prints a table.
Exit status: 0 every workload within the tolerance, 1 some workload grew beyond it, 2 the gate
could not measure (no valgrind, a workload failed, a bad baseline or argument).

  bench/perf/gate.py [--program=PATH] [--baseline=PATH] [--jobs=N] [--workloads=A,B]
  bench/perf/gate.py --update      # measure and rewrite the baseline (a reviewed diff)

Instruction counts of a deterministic program do not depend on the machine's load, so the
gate can run on a shared CI machine where timings cannot.
"""

import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DEFAULT_PROGRAM = os.path.join(ROOT, "build", "release", "bench", "perf", "perf_workloads")
DEFAULT_BASELINE = os.path.join(HERE, "baseline.json")
# Growth allowed before the gate fails, in percent (docs/performance.md gives the reasons:
# run-to-run variation is below 0.01 %, and a 2 % step is a real change of the code).
DEFAULT_TOLERANCE_PERCENT = 2.0
# A workload under valgrind runs for seconds; one that runs for minutes is stuck.
WORKLOAD_TIMEOUT_S = 600


class GateError(Exception):
    """The gate cannot measure: exit status 2."""


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--program", default=DEFAULT_PROGRAM, help="perf_workloads (default: %(default)s)")
    p.add_argument("--baseline", default=DEFAULT_BASELINE, help="the baseline JSON (default: %(default)s)")
    p.add_argument("--jobs", type=int, default=2, help="workloads measured at once (default 2)")
    p.add_argument("--workloads", default="", help="comma-separated names (default: every workload)")
    p.add_argument("--tolerance", type=float, default=None,
                   help="allowed growth in percent (default: the baseline's, else %s)" % DEFAULT_TOLERANCE_PERCENT)
    p.add_argument("--update", action="store_true", help="rewrite the baseline with the counts measured now")
    args = p.parse_args(argv)
    if args.jobs < 1 or args.jobs > 16:
        p.error("--jobs must be in [1, 16]")
    if args.tolerance is not None and not 0 <= args.tolerance <= 100:
        p.error("--tolerance must be in [0, 100]")
    return args


def run_text(command):
    # A fixed environment: its size moves the stack, which moves a workload's count by ~0.01 %.
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "LC_ALL": "C"}
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            timeout=WORKLOAD_TIMEOUT_S, env=env)
    if result.returncode != 0:
        raise GateError("%s exited with %d: %s" % (" ".join(command), result.returncode,
                                                    result.stderr.strip()[-500:]))
    return result.stdout


def list_workloads(program):
    names = [line.split()[0] for line in run_text([program, "--list"]).splitlines() if line.strip()]
    if not names:
        raise GateError("%s --list printed no workload" % program)
    return names


def toolchain(program):
    compiler = run_text([program, "--toolchain"]).strip()
    valgrind = run_text(["valgrind", "--version"]).strip()
    return {"compiler": compiler, "valgrind": valgrind}


def read_instructions(cachegrind_out):
    """The `summary:` line of a cachegrind output file: with --cache-sim=no, Ir alone."""
    with open(cachegrind_out, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("summary:"):
                return int(line.split()[1])
    raise GateError("no summary line in %s" % cachegrind_out)


def measure(program, name, scratch):
    out_file = os.path.join(scratch, name + ".cachegrind")
    stdout = run_text(["valgrind", "--tool=cachegrind", "--cache-sim=no",
                       "--cachegrind-out-file=" + out_file, program, "--workload=" + name])
    expected = name + " checksum="
    line = next((l for l in stdout.splitlines() if l.startswith(expected)), None)
    if line is None:
        raise GateError("%s --workload=%s did not print its checksum" % (program, name))
    return {"instructions": read_instructions(out_file), "checksum": line[len(expected):].strip()}


def measure_all(program, names, jobs):
    scratch = tempfile.mkdtemp(prefix="perf_gate.")
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            futures = {name: pool.submit(measure, program, name, scratch) for name in names}
            return {name: futures[name].result() for name in names}
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def load_baseline(path):
    try:
        with open(path, encoding="utf-8") as f:
            baseline = json.load(f)
    except (OSError, ValueError) as e:
        raise GateError("cannot read the baseline %s: %s" % (path, e))
    workloads = baseline.get("workloads") if isinstance(baseline, dict) else None
    if not isinstance(workloads, dict) or not all(
            isinstance(w, dict) and isinstance(w.get("instructions"), int) and w["instructions"] > 0
            for w in workloads.values()):
        raise GateError("%s: expected {\"workloads\": {NAME: {\"instructions\": N > 0, ...}}}" % path)
    return baseline


def write_baseline(path, tools, tolerance, measured):
    baseline = {
        "about": "Instructions (valgrind Ir) of each perf_workloads workload; bench/perf/gate.py "
                 "compares with them. Rewrite with `bench/perf/gate.py --update`.",
        "toolchain": tools,
        "tolerance_percent": tolerance,
        "workloads": {name: measured[name] for name in sorted(measured)},
    }
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(baseline, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)


def compare(baseline, measured, tolerance):
    """Rows (name, baseline or None, now, change % or None, verdict) and whether any failed."""
    rows, failed = [], False
    for name in sorted(measured):
        now = measured[name]["instructions"]
        before = baseline["workloads"].get(name, {}).get("instructions")
        if before is None:
            rows.append((name, None, now, None, "new: not in the baseline"))
            continue
        change = 100.0 * (now - before) / before
        if change > tolerance:
            verdict, failed = "FAIL: grew beyond %.2f %%" % tolerance, True
        elif change < -tolerance:
            verdict = "faster: update the baseline"
        else:
            verdict = "ok"
        rows.append((name, before, now, change, verdict))
    return rows, failed


def print_table(rows):
    print("%-18s %16s %16s %9s  %s" % ("workload", "baseline Ir", "now Ir", "change", "verdict"))
    for name, before, now, change, verdict in rows:
        print("%-18s %16s %16s %9s  %s" % (
            name, "-" if before is None else "{:,}".format(before), "{:,}".format(now),
            "-" if change is None else "%+.3f %%" % change, verdict))


def main(argv):
    args = parse_args(argv)
    if shutil.which("valgrind") is None:
        raise GateError("valgrind is not installed (apt-get install valgrind)")
    if not os.access(args.program, os.X_OK):
        raise GateError("%s is not built (cmake --build build/release --target perf_workloads)" % args.program)
    names = list_workloads(args.program)
    if args.workloads:
        wanted = args.workloads.split(",")
        unknown = [w for w in wanted if w not in names]
        if unknown:
            raise GateError("unknown workload(s) %s; perf_workloads has %s" % (", ".join(unknown), ", ".join(names)))
        names = wanted
    tools = toolchain(args.program)
    measured = measure_all(args.program, names, args.jobs)
    if args.update:
        tolerance = args.tolerance if args.tolerance is not None else DEFAULT_TOLERANCE_PERCENT
        recorded = {}
        if os.path.exists(args.baseline):
            old = load_baseline(args.baseline)
            if args.tolerance is None:
                tolerance = old.get("tolerance_percent", tolerance)
            if args.workloads:  # a partial update keeps the other workloads' counts
                recorded = {n: w for n, w in old["workloads"].items() if n not in measured}
        recorded.update(measured)
        write_baseline(args.baseline, tools, tolerance, recorded)
        print_table([(n, None, measured[n]["instructions"], None, "recorded") for n in sorted(measured)])
        print("baseline written: %s" % args.baseline)
        return 0
    baseline = load_baseline(args.baseline)
    tolerance = args.tolerance if args.tolerance is not None else float(
        baseline.get("tolerance_percent", DEFAULT_TOLERANCE_PERCENT))
    if baseline.get("toolchain") != tools:
        print("note: the baseline was recorded with %s; this run uses %s: a change of compiler or "
              "valgrind moves the counts (re-record with --update if that is the cause)"
              % (json.dumps(baseline.get("toolchain")), json.dumps(tools)))
    rows, failed = compare(baseline, measured, tolerance)
    print_table(rows)
    if not args.workloads:
        for name in sorted(set(baseline["workloads"]) - set(measured)):
            print("note: %s is in the baseline but perf_workloads has no such workload (not built here?)" % name)
    for name in sorted(measured):
        recorded = baseline["workloads"].get(name, {}).get("checksum")
        if recorded is not None and recorded != measured[name]["checksum"]:
            print("note: %s produced other output than when the baseline was recorded (checksum %s, was %s)"
                  % (name, measured[name]["checksum"], recorded))
    if failed:
        print("instruction-count gate: FAILED (tolerance %.2f %%)" % tolerance)
        return 1
    print("instruction-count gate: passed (tolerance %.2f %%)" % tolerance)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except (GateError, subprocess.TimeoutExpired) as e:
        print("gate.py: %s" % e, file=sys.stderr)
        sys.exit(2)
