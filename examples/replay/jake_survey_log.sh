#!/usr/bin/env bash
# Writes to standard output the mail a shoreside logger records while one vehicle, archie,
# surveys the Jake mission's field (missions/jake/hazards.txt) and then reports: an .alog that
# hazard_replay reads as its input, so the replay and study examples of the docs run anywhere.
#
#   examples/replay/jake_survey_log.sh > jake_inputs.alog
#   hazard_replay missions/jake/jake.moos jake_inputs.alog --seeds=0..2 --score
#
# archie asks for the 25 m sensor at pd 0.9, then mows nine lanes along x from -150 to 400 at
# 1.5 m/s, 36 m apart from y = -90 down to y = -378 (3,300 s), reporting its pose at 10 Hz and
# asking for the sensor every second, as pHazardMgr does. At the end it reports four of the five
# hazards and one benign object (label 82) in a HAZARDSET_REPORT. Every run writes the same
# bytes: nothing is random.
set -euo pipefail

awk 'BEGIN {
  print "%% LOG FILE:       jake_survey_log.sh";
  print "%% LOGSTART        1700000000.000";
  printf "%.3f HAZARD_SEARCH_START shoreside true\n", 0.5;
  printf "%.3f UHZ_CONFIG_REQUEST pHazardMgr_archie vname=archie,width=25,pd=0.9\n", 1.0;
  speed = 1.5; west = -150; east = 400; lanes = 9; top = -90; gap = 36;
  lane_s = (east - west) / speed;
  t = 2.0;
  for (lane = 0; lane < lanes; lane++) {
    y = top - lane * gap;
    heading = (lane % 2 == 0) ? 90 : 270;
    for (k = 0; k <= lane_s * 10; k++) {
      d = k * speed / 10.0;
      x = (lane % 2 == 0) ? west + d : east - d;
      printf "%.3f NODE_REPORT uSimSurveyVehicle_archie NAME=archie,X=%.2f,Y=%.2f,SPD=%.1f,HDG=%d,TYPE=kayak,TIME=%.3f,LENGTH=4\n",
             t, x, y, speed, heading, 1700000000 + t;
      if (k % 10 == 0) printf "%.3f UHZ_SENSOR_REQUEST pHazardMgr_archie vname=archie\n", t;
      t += 0.1;
    }
  }
  printf "%.3f HAZARDSET_REPORT pHazardMgr_archie source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53#x=-64,y=-124,label=98#x=232,y=-80,label=91#x=-41,y=-246,label=82\n", t;
}'
