"""The verdict of a soak run (bench/soak/run.sh): memory after warm-up and every request of the
MOOSDB's .alog accounted for. Prints the figures and exits 1 when the soak failed.

    check_soak.py SAMPLES_CSV DB_ALOG --app-tick=HZ --warmup-s=S --window-s=S --load-s=S
                  [--growth=0.10] [--slack-mb=4]

Memory grows when, for the sensor or the MOOSDB, the largest resident set of the last window
(the last `window-s` simulated seconds of load) exceeds the largest of the first window after
warm-up (`warmup-s` .. `warmup-s` + `window-s`) by more than `growth` (a fraction) plus
`slack-mb`: a process of a few MB keeps a few MB of socket and allocator buffers after a burst
(glibc does not hand them back), which is not growth.

Requests, counted from the .alog (tools/mission_files, the project's reader):
- every UHZ_CONFIG_REQUEST posted once the sensor is up (its first UHZ_OPTIONS_SUMMARY, after
  it registered) has its UHZ_CONFIG_ACK (the sensor acks every request, D11), per vehicle; the
  load generator repeats its first requests until acked, and those posted while the sensor was
  still loading its field reach no one (counted apart as "before start-up");
- every accepted UHZ_CLASSIFY_REQUEST has its UHZ_HAZARD_REPORT. A request is accepted when its
  vehicle holds an unused detection credit for the label: each UHZ_DETECTION_REPORT of
  (vehicle, label) gives one, each accepted request takes one (D7); the others are refused by
  the sensor and need no answer.
"""

import argparse
import collections
import csv
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from mission_files.alog import AlogSkips, read_alog  # noqa: E402

SENSOR = "uFldHazardSensor"
WANTED = {"UHZ_OPTIONS_SUMMARY", "UHZ_CONFIG_REQUEST", "UHZ_CONFIG_ACK", "UHZ_CLASSIFY_REQUEST",
          "UHZ_DETECTION_REPORT", "UHZ_HAZARD_REPORT", "NODE_REPORT", "UHZ_SENSOR_REQUEST"}


def field(value, key):
    """The value of `key` in a comma list of key=value pairs, "" if absent."""
    for pair in value.split(","):
        name, _, v = pair.partition("=")
        if name.strip() == key:
            return v.strip()
    return ""


def count_requests(alog_path):
    counts = collections.Counter()
    config_asked = collections.Counter()
    config_acked = collections.Counter()
    credits = collections.Counter()
    accepted = collections.Counter()
    answered = collections.Counter()
    sensor_up = False
    skips = AlogSkips()   # unusable times and over-long lines: one warning a kind, at the end
    for _time, variable, source, value, _line in read_alog(alog_path, WANTED.__contains__,
                                                           skips=skips):
        counts[variable] += 1
        vname = field(value, "vname")
        if variable == "UHZ_OPTIONS_SUMMARY" and source == SENSOR:
            sensor_up = True
        elif variable == "UHZ_CONFIG_REQUEST":
            if sensor_up:
                config_asked[vname] += 1
            else:
                counts["config_before_start_up"] += 1
        elif variable == "UHZ_CONFIG_ACK":
            config_acked[vname] += 1
        elif variable == "UHZ_DETECTION_REPORT":
            credits[(vname, field(value, "label"))] += 1
        elif variable == "UHZ_CLASSIFY_REQUEST":
            key = (vname, field(value, "label"))
            if credits[key] > 0:
                credits[key] -= 1
                accepted[key] += 1
        elif variable == "UHZ_HAZARD_REPORT":
            answered[(vname, field(value, "label"))] += 1
    for message in skips.warnings(alog_path):
        print("check_soak: " + message, file=sys.stderr)
    config_lost = sum(max(0, n - config_acked[v]) for v, n in config_asked.items())
    classify_lost = sum(max(0, n - answered[k]) for k, n in accepted.items())
    return {
        "node_reports": counts["NODE_REPORT"],
        "sensor_requests": counts["UHZ_SENSOR_REQUEST"],
        "config_requests": counts["UHZ_CONFIG_REQUEST"],
        "config_before_start_up": counts["config_before_start_up"],
        "config_acks": counts["UHZ_CONFIG_ACK"],
        "config_lost": config_lost,
        "detections": counts["UHZ_DETECTION_REPORT"],
        "classify_requests": counts["UHZ_CLASSIFY_REQUEST"],
        "classify_accepted": sum(accepted.values()),
        "classify_answered": sum(min(n, answered[k]) for k, n in accepted.items()),
        "classify_lost": classify_lost,
    }


def read_samples(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def mb(kb):
    return "n/a" if kb is None else f"{kb / 1024:.1f}"


def window_max(samples, column, start_s, end_s):
    values = [s[column] for s in samples if start_s <= s["sim_s"] < end_s]
    return max(values) if values else None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("samples")
    p.add_argument("alog")
    p.add_argument("--app-tick", type=float, required=True)
    p.add_argument("--warmup-s", type=float, required=True)
    p.add_argument("--window-s", type=float, required=True)
    p.add_argument("--load-s", type=float, required=True, help="simulated seconds of load")
    p.add_argument("--growth", type=float, default=0.10)
    p.add_argument("--slack-mb", type=float, default=4.0)
    a = p.parse_args()

    failures = []
    samples = read_samples(a.samples)
    print(f"samples: {len(samples)}")
    for column, who in (("sensor_rss_kb", "sensor"), ("moosdb_rss_kb", "moosdb-lite")):
        first = window_max(samples, column, a.warmup_s, a.warmup_s + a.window_s)
        last = window_max(samples, column, a.load_s - a.window_s, a.load_s + 1)
        start = samples[0][column] if samples else None
        end = samples[-1][column] if samples else None
        print(f"{who} RSS MB: start {mb(start)}, first window after warm-up max {mb(first)}, "
              f"last window max {mb(last)}, end {mb(end)}")
        if first is None or last is None:
            failures.append(f"{who}: no samples in a window")
        elif last > first * (1 + a.growth) + a.slack_mb * 1024:
            failures.append(f"{who}: memory grew {100 * (last / first - 1):.1f} % "
                            f"(> {100 * a.growth:.0f} % + {a.slack_mb:g} MB)")
    worst_gap = max((s["worst_iter_gap"] for s in samples), default=0.0)
    lag_s = max(0.0, worst_gap - 1) / a.app_tick
    print(f"worst iteration gap: {worst_gap:.2f} AppTick periods "
          f"(lag {lag_s:.2f} MOOS s beyond the period)")

    c = count_requests(a.alog)
    print("requests in the .alog: " + ", ".join(f"{k} {v}" for k, v in c.items()))
    if c["config_lost"]:
        failures.append(f"{c['config_lost']} UHZ_CONFIG_REQUEST without an ack")
    if c["classify_lost"]:
        failures.append(f"{c['classify_lost']} accepted UHZ_CLASSIFY_REQUEST without an answer")
    if c["config_requests"] == 0 or c["classify_accepted"] == 0:
        failures.append("no configuration or no accepted classification: the load did not run")
    for f in failures:
        print("FAIL: " + f)
    print("soak: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
