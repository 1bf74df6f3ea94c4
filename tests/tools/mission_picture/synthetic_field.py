#!/usr/bin/env python3
"""A synthetic finished run of any size for the picture tool's tests: a hazard file and an .alog.

  synthetic_field.py OUT_DIR OBJECTS VEHICLES [SEED]   writes OUT_DIR/hazards.txt and run.alog

The field is a square region with OBJECTS objects (a fifth of them hazards, benign ones with an
hr), searched by VEHICLES vehicles, each flying a lawnmower over its own strip of the square.
Every object within a swath of a lane is detected (VIEW_CIRCLE with 12 vertices) and classified
(5 vertices, the right answer three times in four, one answer in 40 changed by aspect: pink);
the last vehicle reports every object answered "hazard" and each other vehicle hands its objects
over to it. Each vehicle has a HAZARDSET_EVAL. Deterministic for a given seed. Python 3 standard
library; the log's format is the one tools/render_mission.py reads (docs/mission-logic.md).
"""

import math
import os
import random
import sys

REGION_SIDE_M = 2000.0
HAZARD_SHARE = 0.2
LANE_SPACING_M = 80.0            # lanes of one vehicle; the swath is 2 x SWATH_HALF_WIDTH_M
SWATH_HALF_WIDTH_M = 40.0
REPORT_STEP_M = 10.0             # NODE_REPORT every 10 m at 2 m/s: every 5 s
SPEED_MPS = 2.0
RIGHT_ANSWER_SHARE = 0.75
ASPECT_CHANGED_SHARE = 1.0 / 40.0


def make_field(n_objects, rng):
    objects = []
    for i in range(n_objects):
        hazard = rng.random() < HAZARD_SHARE
        objects.append({"label": str(i + 1), "hazard": hazard,
                        "x": round(rng.uniform(0, REGION_SIDE_M)),
                        "y": -round(rng.uniform(0, REGION_SIDE_M)),
                        "hr": None if hazard else round(rng.random(), 2)})
    return objects


def hazard_file(objects):
    s = REGION_SIDE_M
    lines = ["// synthetic field for the picture tool's tests",
             "region = pts={0,0:%g,0:%g,%g:0,%g}" % (s, s, -s, -s)]
    for o in objects:
        line = "hazard = x=%d,y=%d,label=%s,type=%s" % (
            o["x"], o["y"], o["label"], "hazard" if o["hazard"] else "benign")
        if o["hr"] is not None:
            line += ",hr=%g" % o["hr"]
        lines.append(line)
    return "\n".join(lines) + "\n"


def lawnmower(x0, x1):
    """Waypoints of north-south lanes over [x0, x1] x [-side, 0]; at least one lane."""
    points, x, down = [], x0 + min(LANE_SPACING_M, x1 - x0) / 2, True
    while x < x1:
        ys = (0.0, -REGION_SIDE_M) if down else (-REGION_SIDE_M, 0.0)
        points += [(x, ys[0]), (x, ys[1])]
        x += LANE_SPACING_M
        down = not down
    return points


def fly(waypoints):
    """(x, y, heading_deg) every REPORT_STEP_M along the waypoints."""
    samples = []
    for (ax, ay), (bx, by) in zip(waypoints, waypoints[1:]):
        length = math.hypot(bx - ax, by - ay)
        heading = math.degrees(math.atan2(bx - ax, by - ay)) % 360.0
        for k in range(int(length // REPORT_STEP_M)):
            f = k * REPORT_STEP_M / length
            samples.append((ax + f * (bx - ax), ay + f * (by - ay), heading))
    if waypoints:
        samples.append((waypoints[-1][0], waypoints[-1][1], samples[-1][2] if samples else 0.0))
    return samples


def make_log(objects, n_vehicles, rng, name_prefix):
    names = ["%s%02d" % (name_prefix, i + 1) for i in range(n_vehicles)]
    strip_m = REGION_SIDE_M / n_vehicles
    lines = ["%% LOG FILE:       synthetic_large.alog", "%% LOGSTART           1700000000.0"]
    post = lambda t, var, src, value: lines.append("%-10.3f %-20s %-16s %s" % (t, var, src, value))
    for name in names:
        post(1.0, "UHZ_CONFIG_ACK", "uFldHazardSensor",
             "vname=%s,width=%g,pd=0.9,pfa=0.5,pclass=0.75" % (name, SWATH_HALF_WIDTH_M))
    answered = {}   # label -> answer type of the last classification
    for i, name in enumerate(names):
        lanes = lawnmower(i * strip_m, (i + 1) * strip_m)
        t = 2.0
        for (x, y, hdg) in fly(lanes):
            post(t, "NODE_REPORT", "uSimSurveyVehicle",
                 "NAME=%s,X=%.1f,Y=%.1f,SPD=%g,HDG=%.0f,TYPE=UUV" % (name, x, y, SPEED_MPS, hdg))
            t += REPORT_STEP_M / SPEED_MPS
        lane_xs = sorted({p[0] for p in lanes})
        for o in objects:
            if not any(abs(o["x"] - lx) <= SWATH_HALF_WIDTH_M for lx in lane_xs):
                continue
            if not i * strip_m <= o["x"] < (i + 1) * strip_m:
                continue
            pink = rng.random() < ASPECT_CHANGED_SHARE
            post(t, "VIEW_CIRCLE", "uFldHazardSensor",
                 "x=%d,y=%d,radius=10,vertices=12,edge_color=white,fill_color=white,"
                 "edge_size=1,fill_transparency=0.3" % (o["x"], o["y"]))
            right = rng.random() < RIGHT_ANSWER_SHARE
            says_hazard = o["hazard"] == right
            colour = "yellow" if says_hazard else "green"
            post(t, "VIEW_CIRCLE", "uFldHazardSensor",
                 "x=%d,y=%d,radius=10,vertices=5,edge_color=%s,fill_color=%s,edge_size=1,"
                 "fill_transparency=0.3" % (o["x"], o["y"], colour, "pink" if pink else colour))
            answered[o["label"]] = "hazard" if says_hazard else "benign"
    final, t_end = names[-1], 1.0e5
    for name in names[:-1]:
        post(t_end, "HAZARD_HANDOVER", "pHazardMgr_" + name,
             "source=%s#dest=%s#prior=0.5#label=1,x=0,y=0" % (name, final))
    reported = [o for o in objects if answered.get(o["label"]) == "hazard"]
    post(t_end + 1, "HAZARDSET_REPORT", "pHazardMgr_" + final,
         "source=%s#name=%s#" % (final, final) +
         "#".join("x=%d,y=%d,label=%s" % (o["x"], o["y"], o["label"]) for o in reported))
    hazards = sum(1 for o in objects if o["hazard"])
    found = sum(1 for o in reported if o["hazard"])
    for name in names:
        post(t_end + 2, "HAZARDSET_EVAL", "uFldHazardMetric",
             "vname=%s,total_score=%d,norm_score=%.2f,score_missed_hazards=%d,"
             "score_false_alarms=%d,score_time_overage=0,missed_hazards=%d,correct_hazards=%d,"
             "false_alarms=%d" % (name, 1000, rng.uniform(20, 90), 100 * (hazards - found),
                                  10 * (len(reported) - found), hazards - found, found,
                                  len(reported) - found))
    return "\n".join(lines) + "\n"


def write(out_dir, n_objects, n_vehicles, seed=1, name_prefix="v"):
    """Writes out_dir/hazards.txt and out_dir/run.alog; returns the objects (dicts). Vehicles
    are named name_prefix + 01, 02, ..."""
    rng = random.Random(seed)
    objects = make_field(n_objects, rng)
    with open(os.path.join(out_dir, "hazards.txt"), "w") as f:
        f.write(hazard_file(objects))
    with open(os.path.join(out_dir, "run.alog"), "w") as f:
        f.write(make_log(objects, n_vehicles, rng, name_prefix))
    return objects


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__.split("\n\n")[1])
    write(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]),
          int(sys.argv[4]) if len(sys.argv) == 5 else 1)
