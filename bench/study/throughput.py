#!/usr/bin/env python3
"""Jake missions per CPU-minute of hazard_study, as a distribution over repeated runs.

    bench/study/throughput.py [--runs=R] [--seeds=S] [--build=DIR] [--against=BINARY]

Runs `hazard_study missions/jake/jake.moos --seeds=1..S` R times (default 15 runs of 20 seeds)
and measures each run's user + system CPU time (os.wait4, microseconds). With --against, a
second hazard_study binary (an older build, say) runs in turn with it, in alternating order, so
both see the same moments of the machine; each pair's ratio is printed too.

Why a distribution: on a shared virtual machine the same process's CPU time varies by a third
from run to run (other tenants, frequency), so one run says little. The middle run (median) is
the figure the docs quote; the fastest and slowest runs bound what to expect.
"""

import argparse
import os
import statistics
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def cpu_seconds(binary, mission, seeds):
    """Runs one study and returns its user + system CPU seconds; fails on a non-zero exit."""
    proc = subprocess.Popen([binary, str(mission), f"--seeds=1..{seeds}"],
                            stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"throughput: {binary} exited with status {status}")
    return usage.ru_utime + usage.ru_stime


def per_minute(seconds, seeds):
    return 60.0 * seeds / seconds


def summary(name, times, seeds):
    rates = sorted(per_minute(t, seeds) for t in times)
    return (f"{name}: missions per CPU-minute: slowest {rates[0]:.0f}, "
            f"middle {statistics.median(rates):.0f}, fastest {rates[-1]:.0f} "
            f"({len(rates)} runs of {seeds} missions)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--build", default=os.environ.get("BUILD_DIR", REPO / "build/release"))
    parser.add_argument("--against", help="a second hazard_study binary, run in turn")
    args = parser.parse_args()
    if args.runs < 1 or args.seeds < 1:
        sys.exit("throughput: --runs and --seeds must be at least 1")
    study = Path(args.build) / "src/apps/hazard_study/hazard_study"
    mission = REPO / "missions/jake/jake.moos"
    binaries = [str(study)] + ([args.against] if args.against else [])
    for b in binaries:
        if not os.access(b, os.X_OK):
            sys.exit(f"throughput: {b} is not an executable")

    times = {b: [] for b in binaries}
    for run in range(args.runs):
        order = binaries if run % 2 == 0 else binaries[::-1]
        for b in order:
            times[b].append(cpu_seconds(b, mission, args.seeds))
        line = "  ".join(f"{per_minute(times[b][-1], args.seeds):6.0f}" for b in binaries)
        print(f"run {run + 1:2d}: {line}", flush=True)

    print(summary(str(study), times[str(study)], args.seeds))
    if args.against:
        print(summary(args.against, times[args.against], args.seeds))
        ratios = sorted(a / b for a, b in zip(times[args.against], times[str(study)]))
        print(f"CPU time of {args.against} / this build, run by run: "
              f"middle {statistics.median(ratios):.3f} "
              f"(from {ratios[0]:.3f} to {ratios[-1]:.3f})")


if __name__ == "__main__":
    main()
