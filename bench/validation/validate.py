#!/usr/bin/env python3
"""Tables of docs/validation.md from pass_bench result files (Python 3 standard library).

    validate.py scene   --ours A.csv [B.csv ...] --original C.csv [D.csv ...] [--margin=0.03]
    validate.py control --ours A.csv [...] --original C.csv [...]

`scene` pools the runs of each program and compares, per figure (detection of hazards, false
alarms of benign objects without hr, with hr=0 and with hr>0, correct classification of each,
detections outside the swath), ours with the original and both with the manual's model:
Wilson 95 % intervals, a two-sided two-proportion z test of ours against the original with
Holm's correction over the figures, a TOST equivalence test with a margin of +-3 percentage
points, and a z test of each program against the model (Holm over both programs' figures);
then per run the detection rates and the passes the pd = 1 vehicle saw as sensor events. `control` prints,
for runs at pd = 1, the detections per pass of each group of objects: every pass of an inside
object and none outside, and the edge groups that show each program's swath length.

The statistics are plain functions, tested in tests/validation without the original.
"""

import argparse
import csv
import io
import math
import sys
from dataclasses import dataclass

Z95 = 1.959963984540054  # two-sided 95 %

KIND_NAMES = {
    "H": "hazard",
    "B": "benign, no hr",
    "B0": "benign, hr=0",
    "Bh": "benign, hr={hr}",
}


# ---------------------------------------------------------------------------------------------
# Statistics

def norm_cdf(z):
    """Standard normal cumulative distribution."""
    return 0.5 * math.erfc(-z / math.sqrt(2.0))


def wilson(k, n, z=Z95):
    """Wilson score interval of k successes in n trials; (0, 1) for n = 0."""
    if n <= 0:
        return 0.0, 1.0
    p = k / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, centre - half), min(1.0, centre + half)


def two_proportion_p(k1, n1, k2, n2):
    """Two-sided p-value of the pooled two-proportion z test; 1 when it cannot differ."""
    if n1 <= 0 or n2 <= 0:
        return 1.0
    pooled = (k1 + k2) / (n1 + n2)
    se = math.sqrt(pooled * (1 - pooled) * (1 / n1 + 1 / n2))
    if se == 0:
        return 1.0
    z = (k1 / n1 - k2 / n2) / se
    return 2 * (1 - norm_cdf(abs(z)))


def one_proportion_p(k, n, p0):
    """Two-sided p-value of the z test that k in n trials come from probability p0.

    For p0 = 0 or 1 an outcome is either possible (every trial as p0 says: 1) or not (0).
    """
    if n <= 0:
        return 1.0
    if p0 <= 0 or p0 >= 1:
        return 1.0 if k == round(n * p0) else 0.0
    z = (k / n - p0) / math.sqrt(p0 * (1 - p0) / n)
    return 2 * (1 - norm_cdf(abs(z)))


def tost_p(k1, n1, k2, n2, margin):
    """p-value of the two one-sided tests that |p1 - p2| < margin (unpooled standard error).

    Small means equivalent. With a zero standard error (both 0 % or both 100 %) the difference
    is known exactly: 0 if it is within the margin, else 1.
    """
    if n1 <= 0 or n2 <= 0:
        return 1.0
    p1, p2 = k1 / n1, k2 / n2
    d = p1 - p2
    se = math.sqrt(p1 * (1 - p1) / n1 + p2 * (1 - p2) / n2)
    if se == 0:
        return 0.0 if abs(d) < margin else 1.0
    p_lower = 1 - norm_cdf((d + margin) / se)  # H0: d <= -margin
    p_upper = norm_cdf((d - margin) / se)      # H0: d >= +margin
    return max(p_lower, p_upper)


def holm(pvalues):
    """Holm-Bonferroni adjusted p-values, in the order given."""
    m = len(pvalues)
    order = sorted(range(m), key=lambda i: pvalues[i])
    adjusted = [0.0] * m
    running = 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (m - rank) * pvalues[i]))
        adjusted[i] = running
    return adjusted


# ---------------------------------------------------------------------------------------------
# The manual's model

def model_detection(kind, pd, exp, hr):
    """Detection probability of an object of `kind` (H, B, B0, Bh) inside the swath."""
    pfa = pd ** exp
    if kind == "H":
        return pd
    if kind == "B":
        return pfa
    if kind == "B0":
        return pfa / 2
    return (pfa + hr) / 2


def model_classification(kind, pclass, hr):
    """Probability that a classification of an object of `kind` names its true type."""
    if kind in ("H", "B"):
        return pclass
    resemblance = 0.0 if kind == "B0" else hr
    return pclass + (1 - pclass) * (1 - resemblance)


# ---------------------------------------------------------------------------------------------
# Result files

@dataclass
class Run:
    header: dict
    rows: dict  # (group, kind) -> dict of counts


def read_run(text):
    """A pass_bench result: `# key=value` lines, then the CSV."""
    header, body = {}, []
    for line in text.splitlines():
        if line.startswith("# "):
            key, _, value = line[2:].partition("=")
            header[key.strip()] = value.strip().strip('"')
        elif line.strip():
            body.append(line)
    rows = {}
    for row in csv.DictReader(io.StringIO("\n".join(body))):
        counts = {k: int(v) for k, v in row.items() if k not in ("group", "kind")}
        rows[(row["group"], row["kind"])] = counts
    return Run(header, rows)


def read_runs(paths):
    """The result files at `paths`; a file that is not one raises ValueError naming it."""
    runs = []
    for path in paths:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        try:
            runs.append(read_run(text))
        except (ValueError, KeyError, TypeError) as error:
            raise ValueError(f"{path}: not a pass_bench result file ({error})") from None
    return runs


def pooled(runs, group, kind, success, trials):
    """Sum of the `success` and `trials` columns of (group, kind) over the runs."""
    k = sum(r.rows.get((group, kind), {}).get(success, 0) for r in runs)
    n = sum(r.rows.get((group, kind), {}).get(trials, 0) for r in runs)
    return k, n


def common_parameter(runs, key):
    values = {r.header.get(key) for r in runs}
    if len(values) != 1 or None in values:
        raise ValueError(f"the runs disagree on {key}: {sorted(map(str, values))}")
    return float(values.pop())


# ---------------------------------------------------------------------------------------------
# Figures and tables

@dataclass
class Figure:
    name: str
    model: float
    ours: tuple      # (k, n)
    original: tuple  # (k, n)


def scene_figures(ours, original):
    """The figures of the scene comparison, from the pooled runs of each program."""
    pd = common_parameter(ours + original, "pd")
    exp = common_parameter(ours + original, "exp")
    pclass = common_parameter(ours + original, "pclass")
    hr = common_parameter(ours + original, "hr")
    figures = []
    for kind in ("H", "B", "B0", "Bh"):
        label = KIND_NAMES[kind].format(hr=f"{hr:g}")
        what = "detection" if kind == "H" else "false alarm"
        figures.append(Figure(f"{what}, {label}", model_detection(kind, pd, exp, hr),
                              pooled(ours, "inside", kind, "detections", "passes"),
                              pooled(original, "inside", kind, "detections", "passes")))
    for kind in ("H", "B", "B0", "Bh"):
        label = KIND_NAMES[kind].format(hr=f"{hr:g}")
        figures.append(Figure(f"correct class, {label}", model_classification(kind, pclass, hr),
                              pooled(ours, "inside", kind, "correct", "answers"),
                              pooled(original, "inside", kind, "correct", "answers")))
    outside = [pooled(runs, "outside", kind, "detections", "passes")
               for runs in (ours, original) for kind in ("H", "B", "B0", "Bh")]
    figures.append(Figure("detected outside the swath", 0.0,
                          tuple(map(sum, zip(*outside[:4]))), tuple(map(sum, zip(*outside[4:])))))
    return figures


def events_seen(runs):
    """(detections, passes) of the pd = 1 vehicle over the inside hazards and benign objects
    without hr: both are detected on every pass that is a sensor event."""
    counts = [pooled(runs, "ctrl_inside", kind, "detections", "passes") for kind in ("H", "B")]
    return tuple(map(sum, zip(*counts)))


def percent(value, decimals=2):
    return f"{100 * value:.{decimals}f}"


def cell(k, n):
    """"k / n = p % [lo, hi]" with the Wilson 95 % interval."""
    if n == 0:
        return "0 / 0"
    lo, hi = wilson(k, n)
    return f"{k} / {n} = {percent(k / n)} % [{percent(lo)}, {percent(hi)}]"


def scene_table(figures, margin):
    """The markdown table of the scene comparison.

    Two families of tests, each Holm-corrected: ours against the original (one test per
    figure), and each program against the model (two tests per figure).
    """
    differ = holm([two_proportion_p(*f.ours, *f.original) for f in figures])
    model = holm([one_proportion_p(*counts, f.model)
                  for f in figures for counts in (f.ours, f.original)])
    lines = [
        "| figure | model | ours | original | ours vs original: p (Holm) "
        f"| equivalent within ±{percent(margin, 0)} points (TOST p) "
        "| vs model: p ours / original (Holm) |",
        "|---|---|---|---|---|---|---|",
    ]
    for i, (f, p_diff) in enumerate(zip(figures, differ)):
        p_equiv = tost_p(*f.ours, *f.original, margin)
        lines.append(f"| {f.name} | {percent(f.model)} % | {cell(*f.ours)} | {cell(*f.original)} "
                     f"| {p_diff:.3f} | {'yes' if p_equiv < 0.05 else 'no'} ({p_equiv:.2g}) "
                     f"| {model[2 * i]:.3f} / {model[2 * i + 1]:.3f} |")
    return "\n".join(lines)


def runs_table(named_runs):
    """One line per run: its seed, its detection rates per kind (the streams differ) and the
    passes the pd = 1 vehicle saw as sensor events; then one pooled line per program."""
    lines = ["| program | seed | lanes | hazard | benign, no hr | benign, hr=0 | benign, hr>0 "
             "| passes sensed (pd = 1 vehicle) | unanswered |",
             "|---|---|---|---|---|---|---|---|---|"]
    programs = []
    for name, _ in named_runs:
        if name not in programs:
            programs.append(name)
    pooled_runs = [(f"{name}, all runs", [r for n, r in named_runs if n == name])
                   for name in programs]
    for name, run in named_runs + pooled_runs:
        runs = run if isinstance(run, list) else [run]
        rates = []
        for kind in ("H", "B", "B0", "Bh"):
            k, n = pooled(runs, "inside", kind, "detections", "passes")
            rates.append(f"{percent(k / n) if n else '-'} %")
        seen = "{} / {}".format(*events_seen(runs))
        seed = runs[0].header.get("seed", "?") if len(runs) == 1 else "-"
        lanes = sum(int(r.header.get("lanes", 0)) for r in runs)
        unanswered = sum(int(r.header.get("unanswered", 0)) for r in runs)
        lines.append(f"| {name} | {seed} | {lanes} | {' | '.join(rates)} | {seen} "
                     f"| {unanswered} |")
    return "\n".join(lines)


CONTROL_GROUPS = [
    ("inside", "H", "hazards inside the swath"),
    ("inside", "B", "benign (no hr) inside the swath"),
    ("outside", None, "every object outside the swath"),
    ("edge_3", "H", "hazards 3 m beyond a lane end"),
    ("edge_7", "H", "hazards 7 m beyond a lane end"),
    ("edge_12", "H", "hazards 12 m beyond a lane end"),
]


def control_table(ours, original):
    """Detections per pass of each group at pd = 1 (every figure exact: 0 or 1)."""
    lines = ["| objects | ours: detections / passes | original: detections / passes |",
             "|---|---|---|"]
    for group, kind, text in CONTROL_GROUPS:
        cells = []
        for runs in (ours, original):
            kinds = [kind] if kind else ["H", "B", "B0", "Bh"]
            k = sum(pooled(runs, group, x, "detections", "passes")[0] for x in kinds)
            n = sum(pooled(runs, group, x, "detections", "passes")[1] for x in kinds)
            cells.append(f"{k} / {n}")
        lines.append(f"| {text} | {cells[0]} | {cells[1]} |")
    return "\n".join(lines)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["scene", "control"])
    parser.add_argument("--ours", nargs="+", required=True, metavar="CSV")
    parser.add_argument("--original", nargs="+", required=True, metavar="CSV")
    parser.add_argument("--margin", type=float, default=0.03,
                        help="equivalence margin, a proportion (default 0.03)")
    args = parser.parse_args(argv)
    try:
        ours, original = read_runs(args.ours), read_runs(args.original)
        if args.mode == "control":
            print(control_table(ours, original))
            return 0
        print(scene_table(scene_figures(ours, original), args.margin))
        print()
        named = [("ours", r) for r in ours] + [("original", r) for r in original]
        print(runs_table(named))
    except (OSError, ValueError, KeyError) as error:
        print(f"validate.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
