#!/usr/bin/env python3
"""The summary of hazard_study's JSON lines, merged from any number of files (one per chunk of a
GNU parallel or Slurm fan-out), and the score plot (docs/study.md).

    study_summary.py [--svg OUT.svg] [--cpu CPU.json] [--title TEXT] FILE.jsonl...

Prints, per setting in the order first seen: missions, scored missions, mean score, standard
deviation, the 95 % confidence interval of the mean (Student's t), missions stopped at max_time
and, with --cpu (a JSON object {setting: CPU seconds per mission}), the CPU per mission, as a
Markdown table. --svg draws each setting's score distribution (a histogram of 2.5-point bins)
with its mean and interval, in the style of bench/accuracy/plot_accuracy.py. Standard library
only. A line that is not one of hazard_study's objects is skipped and counted (one warning per
file); a line over 1 MB is skipped too. Exit status 0, 1 when a file cannot be read or nothing
was scored.
"""
import argparse
import json
import math
import sys
from xml.sax.saxutils import escape

MAX_LINE = 1 << 20
BIN = 2.5


def t975(df):
    small = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228]
    if df <= 10:
        return small[df - 1]
    z, n = 1.959963984540054, float(df)
    return z + (z ** 3 + z) / (4 * n) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * n * n)


def read_lines(paths):
    settings = {}
    for path in paths:
        skipped = 0
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                for line in f:
                    row = parse(line)
                    if row is None:
                        skipped += 1
                        continue
                    s = settings.setdefault(row["setting"], {"missions": 0, "scores": [], "max_time": 0})
                    s["missions"] += 1
                    if isinstance(row.get("score"), (int, float)) and math.isfinite(row["score"]):
                        s["scores"].append(float(row["score"]))
                    if row.get("end") == "max_time":
                        s["max_time"] += 1
        except OSError as e:
            sys.exit("study_summary.py: %s: %s" % (path, e.strerror))
        if skipped:
            print("study_summary.py: %s: %d lines are not hazard_study lines (skipped)" % (path, skipped),
                  file=sys.stderr)
    return settings


def parse(line):
    if len(line) > MAX_LINE:
        return None
    try:
        row = json.loads(line)
    except ValueError:
        return None
    if not isinstance(row, dict) or not isinstance(row.get("setting"), str):
        return None
    return row


def stats(xs):
    n = len(xs)
    mean = sum(xs) / n
    if n < 2:
        return mean, None, None
    sd = math.sqrt(sum((x - mean) ** 2 for x in xs) / (n - 1))
    return mean, sd, t975(n - 1) * sd / math.sqrt(n)


def table(settings, cpu):
    head = "| setting | missions | mean score | sd | 95 % interval | max_time |"
    rule = "|---|---:|---:|---:|---|---:|"
    if cpu:
        head += " CPU per mission |"
        rule += "---:|"
    out = [head, rule]
    for label, s in settings.items():
        if not s["scores"]:
            row = "| %s | %d | - | - | - | %d |" % (label, s["missions"], s["max_time"])
        else:
            mean, sd, half = stats(s["scores"])
            row = "| %s | %d | %.2f | %s | %s | %d |" % (
                label, s["missions"], mean, "-" if sd is None else "%.2f" % sd,
                "-" if half is None else "%.2f to %.2f" % (mean - half, mean + half), s["max_time"])
        if cpu:
            row += " %s |" % ("%.0f ms" % (1000 * cpu[label]) if label in cpu else "-")
        out.append(row)
    return "\n".join(out)


def svg_plot(settings, title):
    rows = [(label, s) for label, s in settings.items() if s["scores"]]
    row_h, left, width, top = 46, 260, 520, 60
    height = top + row_h * len(rows) + 60
    lo = min(min(s["scores"]) for _, s in rows)
    lo = max(0.0, math.floor(lo / 10) * 10)
    x = lambda v: left + (v - lo) / (100 - lo) * width
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">'
           % (left + width + 40, height, left + width + 40, height),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="28" font-size="15" font-weight="bold" text-anchor="middle" '
           'font-family="sans-serif">%s</text>' % ((left + width + 40) // 2, escape(title))]
    bottom = top + row_h * len(rows)
    tick = 10 if 100 - lo > 30 else 5
    v = lo
    while v <= 100.001:
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x(v), top, x(v), bottom))
        out.append('<text x="%.1f" y="%d" font-size="11" text-anchor="middle" font-family="sans-serif">%g</text>'
                   % (x(v), bottom + 16, v))
        v += tick
    out.append('<text x="%.1f" y="%d" font-size="12" text-anchor="middle" font-family="sans-serif">'
               'score (bars: share of missions per %.1f-point bin; dot and line: mean and 95 %% interval)</text>'
               % (left + width / 2, bottom + 36, BIN))
    for i, (label, s) in enumerate(rows):
        y0 = top + i * row_h
        bins = {}
        for v in s["scores"]:
            b = min(int((v - lo) // BIN), int((100 - lo) // BIN) - 1)
            bins[b] = bins.get(b, 0) + 1
        peak = max(bins.values())
        for b, count in bins.items():
            h = (row_h - 14) * count / peak
            out.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="#9ecae1"/>'
                       % (x(lo + b * BIN), y0 + row_h - 6 - h, x(lo + BIN) - x(lo) - 1, h))
        mean, _, half = stats(s["scores"])
        yc = y0 + row_h - 6
        if half is not None:
            out.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#d62728" stroke-width="3"/>'
                       % (x(max(lo, mean - half)), yc, x(min(100, mean + half)), yc))
        out.append('<circle cx="%.1f" cy="%.1f" r="4" fill="#d62728"/>' % (x(mean), yc))
        out.append('<text x="%d" y="%.1f" font-size="12" text-anchor="end" font-family="sans-serif">%s</text>'
                   % (left - 10, y0 + row_h / 2 + 6, escape(label)))
        out.append('<text x="%d" y="%.1f" font-size="10" text-anchor="end" font-family="sans-serif" '
                   'fill="#555">mean %.2f, n = %d</text>' % (left - 10, y0 + row_h / 2 + 19, mean, len(s["scores"])))
    out.append('</svg>')
    return "\n".join(out) + "\n"


def main():
    p = argparse.ArgumentParser(description="Summary and plot of hazard_study's JSON lines.")
    p.add_argument("files", nargs="+")
    p.add_argument("--svg")
    p.add_argument("--cpu")
    p.add_argument("--title", default="Jake mission score per setting")
    a = p.parse_args()
    settings = read_lines(a.files)
    if not any(s["scores"] for s in settings.values()):
        sys.exit("study_summary.py: no scored mission in the input")
    cpu = {}
    if a.cpu:
        try:
            with open(a.cpu) as f:
                cpu = {k: float(v) for k, v in json.load(f).items()}
        except (OSError, ValueError, AttributeError) as e:
            sys.exit("study_summary.py: --cpu %s: %s" % (a.cpu, e))
    print(table(settings, cpu))
    if a.svg:
        try:
            with open(a.svg, "w") as f:
                f.write(svg_plot(settings, a.title))
        except OSError as e:
            sys.exit("study_summary.py: --svg %s: %s" % (a.svg, e.strerror))


if __name__ == "__main__":
    main()
