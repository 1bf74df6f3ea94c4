#!/usr/bin/env python3
"""Live mission against lockstep, in distribution (bench/study/live_compare.sh; docs/study.md).

    compare_live.py LIVE_DIR LOCKSTEP.jsonl

LIVE_DIR holds one run folder per seed (live-<seed>/summary.json, written by
missions/jake/launch.sh); LOCKSTEP.jsonl is hazard_study's output for the same seeds. Prints the
two score samples' means, the Mann-Whitney U test (normal approximation with the tie
correction, two-sided) and the two-sample Kolmogorov-Smirnov test (asymptotic p-value), then
the seeds whose two runs differ. Python standard library only.
"""
import glob
import json
import math
import os
import sys


def mann_whitney(a, b):
    """U of sample a, and the two-sided p-value (normal approximation, ties corrected)."""
    pooled = sorted([(v, 0) for v in a] + [(v, 1) for v in b])
    ranks = [0.0] * len(pooled)
    i, ties = 0, 0.0
    while i < len(pooled):
        j = i
        while j + 1 < len(pooled) and pooled[j + 1][0] == pooled[i][0]:
            j += 1
        for k in range(i, j + 1):
            ranks[k] = (i + j) / 2.0 + 1.0
        t = j - i + 1
        ties += t ** 3 - t
        i = j + 1
    n1, n2 = len(a), len(b)
    r1 = sum(r for r, (_, g) in zip(ranks, pooled) if g == 0)
    u = r1 - n1 * (n1 + 1) / 2.0
    n = n1 + n2
    var = n1 * n2 / 12.0 * ((n + 1) - ties / (n * (n - 1)))
    if var <= 0:
        return u, 1.0
    z = (abs(u - n1 * n2 / 2.0) - 0.5) / math.sqrt(var)
    return u, min(1.0, math.erfc(max(z, 0.0) / math.sqrt(2)))


def kolmogorov_smirnov(a, b):
    """D and the asymptotic two-sided p-value."""
    values = sorted(set(a) | set(b))
    d = max(abs(sum(x <= v for x in a) / len(a) - sum(x <= v for x in b) / len(b)) for v in values)
    ne = len(a) * len(b) / (len(a) + len(b))
    lam = (math.sqrt(ne) + 0.12 + 0.11 / math.sqrt(ne)) * d
    p = 2 * sum((-1) ** (k - 1) * math.exp(-2 * k * k * lam * lam) for k in range(1, 101))
    return d, max(0.0, min(1.0, p))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    live = {}
    for path in glob.glob(os.path.join(sys.argv[1], "live-*", "summary.json")):
        with open(path) as f:
            s = json.load(f)
        if isinstance(s.get("score"), (int, float)):
            live[int(s["seed"])] = s
    lock = {}
    with open(sys.argv[2]) as f:
        for line in f:
            r = json.loads(line)
            if isinstance(r.get("score"), (int, float)):
                lock[r["seed"]] = r
    seeds = sorted(set(live) & set(lock))
    # summary.json keeps two decimals: compare both at that precision.
    a = [round(live[s]["score"], 2) for s in seeds]
    b = [round(lock[s]["score"], 2) for s in seeds]
    if len(seeds) < 2:
        sys.exit("fewer than two seeds with a score in both")
    u, p_u = mann_whitney(a, b)
    d, p_d = kolmogorov_smirnov(a, b)
    print("seeds %d: live mean %.2f sd %.2f, lockstep mean %.2f sd %.2f" % (
        len(seeds), sum(a) / len(a), stdev(a), sum(b) / len(b), stdev(b)))
    print("Mann-Whitney U = %.1f, p = %.3f" % (u, p_u))
    print("Kolmogorov-Smirnov D = %.3f, p = %.3f" % (d, p_d))
    differ = [(s, x, y) for s, x, y in zip(seeds, a, b) if x != y]
    print("same score on %d of %d seeds" % (len(seeds) - len(differ), len(seeds)))
    for s, x, y in differ:
        print("  seed %d: live %.2f, lockstep %.2f" % (s, x, y))


def stdev(xs):
    m = sum(xs) / len(xs)
    return math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1))


if __name__ == "__main__":
    main()
