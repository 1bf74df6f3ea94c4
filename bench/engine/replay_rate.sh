#!/usr/bin/env bash
# hazard_replay's digest rate: node reports per CPU second in a 1,000,000-object
# field (gen_hazards, 20 km square, half hazards, --seed=1), 100 vehicles mowing lanes at
# 1.5 m/s with 10 Hz node reports, AppTick 4, markers off, swath visuals on (the default).
# The CPU time (user + system, /usr/bin/time) of a replay of DURATION simulated seconds minus
# that of a 1-second replay (loading the field) is divided by the node reports between them.
#
#   bench/engine/replay_rate.sh [DURATION_S (default 300)] [--study]
# --study times the study mode instead (`--seeds=1..1`: one JSON line, no .alog, no visuals).
# BUILD_DIR (default build/release) is where hazard_replay and gen_hazards were built.
# RUNS=N (default 1) times each replay N times and keeps the smallest CPU time of each (the
# rest is other jobs on a shared machine; 300 s of reports take a few tenths of a CPU second).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build/release}"
REPLAY="$BUILD/src/apps/hazard_replay/hazard_replay"
GEN="$BUILD/src/apps/gen_hazards/gen_hazards"
for p in "$REPLAY" "$GEN"; do [[ -x "$p" ]] || { echo "replay_rate.sh: build $p first" >&2; exit 1; }; done
DURATION="${1:-300}"
RUNS="${RUNS:-1}"
[[ "$RUNS" =~ ^[1-9][0-9]?$ ]] || { echo "replay_rate.sh: RUNS must be in [1, 99]: '$RUNS'" >&2; exit 2; }
STUDY="${2:-}"
[[ -z "$STUDY" || "$STUDY" == --study ]] ||
  { echo "replay_rate.sh: the second argument may only be --study: '$STUDY'" >&2; exit 2; }
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 2 && "$DURATION" -le 36000 ]] ||
  { echo "replay_rate.sh: DURATION_S must be a whole number in [2, 36000]: '$DURATION'" >&2; exit 2; }
WORK="$(mktemp -d /tmp/replay_rate.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
MODE=(--output="$WORK/out.alog")
if [[ -n "$STUDY" ]]; then MODE=(--seeds=1..1); fi

"$GEN" --polygon=-10000,-10000:10000,-10000:10000,10000:-10000,10000 \
  --objects=500000,hazard --objects=500000,benign --seed=1 > "$WORK/field.txt"
cat > "$WORK/m.moos" <<MOOS
ServerPort = 9000
Community = shoreside
ProcessConfig = uFldHazardSensor
{
  AppTick = 4
  hazard_file = field.txt
  sensor_config = width=25, exp=4, pclass=0.8
  swath_length = 5
  random_seed = 1
  show_hazards = false
}
MOOS

# DURATION seconds of 100 vehicles, lanes 200 m apart, west to east and back, 10 Hz.
make_log() {
  awk -v T="$1" 'BEGIN {
    print "%% LOGSTART 1700000000.0";
    for (v = 0; v < 100; v++) printf "0.000 UHZ_SENSOR_REQUEST bench vname=v%d\n", v;
    for (k = 1; k <= T * 10; k++) {
      t = k / 10.0; d = (t * 1.5) % 40000; x = d < 20000 ? d - 10000 : 30000 - d;
      h = d < 20000 ? 90 : 270;
      for (v = 0; v < 100; v++)
        printf "%.3f NODE_REPORT bench NAME=v%d,X=%.2f,Y=%.1f,SPD=1.5,HDG=%d,TYPE=kayak,TIME=%.3f,LENGTH=4\n",
               t, v, x, -9900 + v * 200, h, 1700000000 + t;
      if (k % 1000 == 0) for (v = 0; v < 100; v++) printf "%.3f UHZ_SENSOR_REQUEST bench vname=v%d\n", t, v;
    }
  }' > "$2"
}
make_log 1 "$WORK/short.alog"
make_log "$DURATION" "$WORK/long.alog"

cpu() {  # the smallest user + system seconds of RUNS replays
  local best=""
  for ((run = 0; run < RUNS; ++run)); do
    rm -f "$WORK/out.alog"  # freeing the last run's 100 MB of output is not this run's work
    /usr/bin/time -f "%U %S" -o "$WORK/time" "$REPLAY" "$WORK/m.moos" "$1" "${MODE[@]}" \
      >/dev/null 2>&1
    best=$(awk -v best="$best" '{ s = $1 + $2; print (best == "" || s < best) ? s : best }' "$WORK/time")
  done
  echo "$best"
}
short_s=$(cpu "$WORK/short.alog")
long_s=$(cpu "$WORK/long.alog")
reports=$(( (DURATION - 1) * 10 * 100 ))
awk -v s="$short_s" -v l="$long_s" -v n="$reports" 'BEGIN {
  printf "load + 1 s: %.2f CPU s; %d node reports more: %.2f CPU s more; %.0f node reports per CPU second\n",
         s, n, l - s, n / (l - s) }'
