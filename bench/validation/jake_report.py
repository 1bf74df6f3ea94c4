#!/usr/bin/env python3
"""The side-by-side table of a Jake mission run with each sensor (bench/validation/jake.sh).

    jake_report.py --ours RUN_DIR... --original RUN_DIR...

Each RUN_DIR holds the mission copy (hazards.txt, the ground truth) and the shoreside's
LOG_SHORESIDE_*/*.alog. From the log (each posting once: the identical lines pLogger's wildcard
logging writes when it registers a variable anew are skipped), per run: the grader's HAZARD_SEARCH_SCORE and
HAZARDSET_EVAL per vehicle, the sensor's detections of hazards and of benign objects, its
classification answers and how many named the true type, the configuration requests and the
acknowledgement variables and texts, and the run warnings of the sensor's last AppCast.
Python 3 standard library; the .alog and hazard-file readers are tools/mission_files.
"""

import argparse
import glob
import os
import sys
from collections import Counter

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from mission_files.alog import read_alog  # noqa: E402
from mission_files.hazard_file import read_hazard_file  # noqa: E402

VEHICLES = ("archie", "betty")
WANTED = {"HAZARD_SEARCH_SCORE", "UHZ_DETECTION_REPORT", "UHZ_HAZARD_REPORT",
          "UHZ_CONFIG_REQUEST", "UHZ_CLASSIFY_REQUEST", "APPCAST"}


def fields(text):
    """key=value pairs of a comma list (the first '=' splits)."""
    out = {}
    for part in text.split(","):
        key, _, value = part.partition("=")
        out.setdefault(key.strip(), value.strip())
    return out


def appcast_items(text):
    """The items of an APPCAST string (separated by '!@#')."""
    out = {}
    for item in text.split("!@#"):
        key, _, value = item.partition("=")
        out.setdefault(key, value)
    return out


def read_run(run_dir):
    logs = sorted(glob.glob(os.path.join(run_dir, "LOG_SHORESIDE*", "*.alog")))
    if not logs:
        raise ValueError(f"{run_dir}: no LOG_SHORESIDE*/*.alog")
    truth = {o["label"]: o["hazard"] for o in read_hazard_file(
        os.path.join(run_dir, "hazards.txt")).objects}
    r = {"scores": [], "evals": {}, "detections": Counter(), "answers": Counter(),
         "correct": Counter(), "config_requests": Counter(), "classify_requests": Counter(),
         "acks": Counter(), "warnings": "-", "run_warning_total": "-"}

    def wanted(var):
        return var in WANTED or var.startswith(("UHZ_CONFIG_ACK", "HAZARDSET_EVAL_"))

    seen = set()
    for time_s, var, source, value, _ in read_alog(logs[0], wanted):
        value = value.strip()
        # pLogger's wildcard logging writes a variable's current value again, with its original
        # time, each time it registers anew: one posting, several identical lines.
        if (time_s, var, source, value) in seen:
            continue
        seen.add((time_s, var, source, value))
        f = fields(value)
        if var == "HAZARD_SEARCH_SCORE":
            r["scores"].append(value)
        elif var.startswith("HAZARDSET_EVAL_"):
            r["evals"][var[len("HAZARDSET_EVAL_"):].lower()] = value
        elif var == "UHZ_DETECTION_REPORT" and f.get("vname") in VEHICLES:
            kind = "hazard" if truth.get(f.get("label")) else "benign"
            r["detections"][(f["vname"], kind)] += 1
        elif var == "UHZ_HAZARD_REPORT" and f.get("vname") in VEHICLES:
            r["answers"][f["vname"]] += 1
            if (f.get("type") == "hazard") == bool(truth.get(f.get("label"))):
                r["correct"][f["vname"]] += 1
        elif var == "UHZ_CONFIG_REQUEST":
            r["config_requests"][f.get("vname", "?")] += 1
        elif var == "UHZ_CLASSIFY_REQUEST":
            r["classify_requests"][f.get("vname", "?")] += 1
        elif var.startswith("UHZ_CONFIG_ACK") and source.startswith("uFldHazardSensor"):
            r["acks"][f"{var} = {value}"] += 1
        elif var == "APPCAST" and value.startswith("proc=uFldHazardSensor"):
            items = appcast_items(value)
            r["run_warning_total"] = items.get("run_warning_total", "-")
            r["warnings"] = items.get("run_warnings", "") or "none"
    return r


def evals(run, key):
    """`key` of the grader's HAZARDSET_EVAL_<V> for each vehicle ("-" where there is none)."""
    return " / ".join(fields(run["evals"][v]).get(key, "-") if v in run["evals"] else "-"
                      for v in VEHICLES)


def per_vehicle(counter, kind=None):
    return " / ".join(str(counter[(v, kind)] if kind else counter[v]) for v in VEHICLES)


def table(named):
    """Markdown: one column per run."""
    rows = [
        ("HAZARD_SEARCH_SCORE (per graded report)", lambda r: ", ".join(r["scores"]) or "-"),
        ("grader: norm_score, archie / betty", lambda r: evals(r, "norm_score")),
        ("grader: correct hazards, archie / betty", lambda r: evals(r, "correct_hazards")),
        ("grader: missed hazards, archie / betty", lambda r: evals(r, "missed_hazards")),
        ("grader: false alarms, archie / betty", lambda r: evals(r, "false_alarms")),
        ("grader: total_time (s), archie / betty",
         lambda r: " / ".join(f"{float(t):.0f}" if t != "-" else t
                              for t in evals(r, "total_time").split(" / "))),
        ("detections of hazards, archie / betty", lambda r: per_vehicle(r["detections"], "hazard")),
        ("detections of benign objects, archie / betty",
         lambda r: per_vehicle(r["detections"], "benign")),
        ("classify requests, archie / betty", lambda r: per_vehicle(r["classify_requests"])),
        ("classification answers, archie / betty", lambda r: per_vehicle(r["answers"])),
        ("answers naming the true type, archie / betty", lambda r: per_vehicle(r["correct"])),
        ("UHZ_CONFIG_REQUEST, archie / betty", lambda r: per_vehicle(r["config_requests"])),
        ("acknowledgements (variable = value: postings)",
         lambda r: "<br>".join(f"`{k}`: {n}" for k, n in sorted(r["acks"].items())) or "-"),
        ("sensor run warnings (total; count:text)",
         lambda r: f"{r['run_warning_total']}; {r['warnings']}"),
    ]
    lines = ["| | " + " | ".join(name for name, _ in named) + " |",
             "|---|" + "---|" * len(named)]
    for label, get in rows:
        cells = [str(get(r)).replace("|", "\\|").replace("!@", "; ") for _, r in named]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ours", nargs="+", required=True, metavar="RUN_DIR")
    parser.add_argument("--original", nargs="+", required=True, metavar="RUN_DIR")
    args = parser.parse_args(argv)
    try:
        named = []
        for i, (ours, original) in enumerate(zip(args.ours, args.original), 1):
            named.append((f"original, run {i}", read_run(original)))
            named.append((f"ours, run {i}", read_run(ours)))
    except (OSError, ValueError) as error:
        print(f"jake_report.py: {error}", file=sys.stderr)
        return 1
    print(table(named))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
