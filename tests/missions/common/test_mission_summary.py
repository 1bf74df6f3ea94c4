#!/usr/bin/env python3
"""missions/common/mission_summary.py on a synthetic run: summary.json's fields (counts split by
ground truth, the acknowledged setting, the latest evaluation per vehicle as numbers, simulated
time from DEPLOY_ALL to the final vehicle's evaluation, CPU per process), the printed score
table, malformed lines skipped, and a clean failure for a missing log; `nan` is not a number
(the base grammar, include/base/text.hpp): not a time, not a setting, not a score, and
summary.json stays strict JSON.

Usage: test_mission_summary.py PATH/TO/mission_summary.py
"""

import json
import os
import subprocess
import sys
import tempfile

SCRIPT = sys.argv[1]

HAZARDS = """// a field of three
region = pts={0,0:10,0:10,-10:0,-10}
hazard = x=1,y=-1,label=h1,type=hazard
hazard = x=2,y=-2,label=b1,type=benign
hazard = x=3,y=-3,label=b2,type=benign
"""

ALOG = """%% LOG FILE:       run.alog
%% LOGSTART           1700000000.000
%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%
5.000      DEPLOY_ALL           launch-1         true
6.000      UHZ_CONFIG_ACK       uFldHazardSensor vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.85
10.000     UHZ_DETECTION_REPORT uFldHazardSensor vname=archie,x=1,y=-1,label=h1
11.000     UHZ_DETECTION_REPORT uFldHazardSensor vname=archie,x=2,y=-2,label=b1
11.500     UHZ_DETECTION_REPORT_ARCHIE uFldHazardSensor x=2,y=-2,label=b1
12.000     UHZ_HAZARD_REPORT    uFldHazardSensor vname=archie,x=1,y=-1,label=h1,type=hazard
13.000     UHZ_HAZARD_REPORT    uFldHazardSensor vname=archie,x=2,y=-2,label=b1,type=hazard
this line is not an alog line
20.000     HAZARDSET_REPORT     pHazardMgr_archie source=archie#name=archie#x=1,y=-1,label=h1#x=2,y=-2,label=b1
20.100     HAZARDSET_EVAL       uFldHazardMetric vname=archie,report_name=archie,total_score=10,norm_score=95.24,missed_hazards=0,correct_hazards=1,false_alarms=1
21.000     HAZARD_HANDOVER      pHazardMgr_archie source=archie#dest=betty#prior=0.5#label=h1,x=1,y=-1,evidence=2
30.000     HAZARDSET_REPORT     pHazardMgr_betty source=betty#name=betty#x=1,y=-1,label=h1
30.200     HAZARDSET_EVAL       uFldHazardMetric vname=betty,report_name=betty,total_score=0,norm_score=100,missed_hazards=0,correct_hazards=1,false_alarms=0
"""

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


with tempfile.TemporaryDirectory() as d:
    alog, hazards, out, cpu = (os.path.join(d, n) for n in ("run.alog", "h.txt", "s.json", "cpu.txt"))
    open(alog, "w").write(ALOG)
    open(hazards, "w").write(HAZARDS)
    open(cpu, "w").write("moosdb-lite 0.50 1.25\nuFldHazardSensor 1 2\nbroken line\n")
    r = subprocess.run([sys.executable, SCRIPT, "--alog", alog, "--hazards", hazards, "--out", out,
                        "--title", "T", "--mission", "m", "--seed", "7", "--warp", "400",
                        "--real-seconds", "12.5", "--cpu", cpu, "--final", "betty"],
                       capture_output=True, text=True)
    check(r.returncode == 0, "exit 0: %s" % r.stderr)
    check("1 malformed log lines skipped" in r.stderr, "malformed line reported: %r" % r.stderr)
    s = json.load(open(out))
    check(s["seed"] == 7 and s["warp"] == 400 and s["mission"] == "m", "launch fields")
    check(abs(s["sim_seconds"] - 25.2) < 1e-9, "sim_seconds from DEPLOY_ALL to betty's eval: %r" % s["sim_seconds"])
    check(s["score"] == 100, "score = the final vehicle's norm_score")
    check(s["truth"] == {"hazards": 1, "benign": 2}, "truth counts")
    a = s["vehicles"]["archie"]
    check(a["setting"] == {"width": 25, "pd": 0.9, "pfa": 0.656, "pclass": 0.85}, "acked setting %r" % a["setting"])
    check((a["detections"], a["hazard_detections"], a["benign_detections"]) == (2, 1, 1),
          "detections by truth (the _<V> copy not counted twice)")
    check((a["classifications"], a["correct_classifications"]) == (2, 1), "classifications and right ones")
    check(a["reported"] == 2 and s["vehicles"]["betty"]["reported"] == 1, "report sizes")
    check(a["handovers_sent"] == 1, "hand-overs")
    check([e["vname"] for e in s["evals"]] == ["archie", "betty"], "evals per vehicle")
    check(s["evals"][0]["norm_score"] == 95.24 and s["evals"][0]["false_alarms"] == 1, "evals as numbers")
    check(s["processes"] == [{"name": "moosdb-lite", "cpu_user_s": 0.5, "cpu_system_s": 1.25},
                             {"name": "uFldHazardSensor", "cpu_user_s": 1, "cpu_system_s": 2}],
          "cpu %r" % s["processes"])
    check("Mission score (betty's report): 100.00 / 100" in r.stdout, "score line")
    check("archie   25/0.9/0.656/0.85" in r.stdout, "table row: %s" % r.stdout)
    check("CPU seconds (user+system): 4.8 in all" in r.stdout, "cpu line")

    missing = subprocess.run([sys.executable, SCRIPT, "--alog", os.path.join(d, "none.alog"),
                              "--hazards", hazards, "--out", out], capture_output=True, text=True)
    check(missing.returncode == 1 and "none.alog" in missing.stderr, "a missing log: exit 1, named")

NAN_ALOG = """%% LOG FILE:       nan.alog
5.000      DEPLOY_ALL           launch-1         true
nan        DEPLOY_ALL           launch-1         true
-inf       DEPLOY_ALL           launch-1         true
1e300      DEPLOY_ALL           launch-1         true
6.000      UHZ_CONFIG_ACK       uFldHazardSensor vname=archie,width=nan,pd=inf,pfa=0.5,pclass=0.8
20.100     HAZARDSET_EVAL       uFldHazardMetric vname=archie,norm_score=nan,missed_hazards=0,correct_hazards=1,false_alarms=inf
"""


def strict_json(path):
    """The JSON at path, failing on NaN and Infinity (not JSON, though Python writes them)."""
    def refuse(word):
        raise ValueError("not JSON: " + word)
    with open(path) as f:
        return json.load(f, parse_constant=refuse)


with tempfile.TemporaryDirectory() as d:
    alog, hazards, out = (os.path.join(d, n) for n in ("nan.alog", "h.txt", "s.json"))
    open(alog, "w").write(NAN_ALOG)
    open(hazards, "w").write(HAZARDS + "hazard = x=nan,y=1,label=n1,type=hazard\n")
    r = subprocess.run([sys.executable, SCRIPT, "--alog", alog, "--hazards", hazards, "--out", out,
                        "--final", "archie"], capture_output=True, text=True)
    check(r.returncode == 0, "nan run: exit 0: %s" % r.stderr)
    check("3 lines with unusable times (not finite, or beyond 1e10 s) skipped" in r.stderr,
          "times of nan, -inf and 1e300 are skipped and counted once: %r" % r.stderr)
    check("malformed" not in r.stderr, "no warning a line: %r" % r.stderr)
    try:
        s = strict_json(out)
    except ValueError as e:
        s = None
        check(False, "summary.json with nan values is strict JSON: %s" % e)
    if s is not None:
        check(s["truth"] == {"hazards": 1, "benign": 2},
              "an object at x=nan is not truth: %r" % s["truth"])
        setting = s["vehicles"]["archie"]["setting"]
        check(setting == {"width": None, "pd": None, "pfa": 0.5, "pclass": 0.8},
              "nan and inf settings are missing: %r" % setting)
        e = s["evals"][0]
        check(e["norm_score"] == "nan" and e["false_alarms"] == "inf" and e["correct_hazards"] == 1,
              "non-numbers in an evaluation stay text: %r" % e)
        check(s["score"] is None, "a nan score is no score: %r" % s["score"])
    check("Mission score (archie's report): - / 100" in r.stdout,
          "nan score shown as -: %s" % r.stdout)
    check("archie   -/-/0.5/0.8" in r.stdout, "nan setting shown as -: %s" % r.stdout)

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("mission_summary: all checks passed")
