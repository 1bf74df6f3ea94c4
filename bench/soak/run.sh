#!/usr/bin/env bash
# Soak (docs/robustness.md "Soak"): on demand, not in the test suite.
#
#   bench/soak/run.sh [--hours=H] [--warp=W] [--vehicles=V] [--objects=N] [--work-dir=DIR]
#                     [-- PROCESS_BENCH_OPTIONS...]
#
# Plays V vehicles (default 100) over a field of N objects (default 100,000) for H simulated
# hours (default 8) at warp W (default 100) against uFldHazardSensor through moosdb-lite with
# --log on, with every request type at field rates per vehicle: NODE_REPORT 1 Hz,
# UHZ_SENSOR_REQUEST 1 Hz, UHZ_CONFIG_REQUEST every 10 min, UHZ_CLASSIFY_REQUEST every 40 s
# (the newest unclassified detection; min_classify_interval is 30 s). Every simulated minute
# it samples the resident memory of the sensor and moosdb-lite and the sensor's worst
# iteration gap. Then check_soak.py judges: memory must not grow after warm-up (the last
# eighth of the run's max RSS at most 10 % + 4 MB above that of the eighth after a one-eighth
# warm-up; 8 h: hours 8 against hour 2) and every request in the .alog must be answered.
# Exit 0: passed; 1: failed (the work folder is kept either way). Runs shorter than half an hour
# leave the windows (an eighth each) without a sample: they fail with "no samples in a window".
# What the sensor's memory holds over the run: build/release/bench/soak/soak_heap WORK_DIR
# replays the run's .alog through the engine (soak_heap.cpp).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BENCH="${BUILD_DIR:-$ROOT/build/release}/bench/process/process_bench"
PYTHON="${HAZARD_PYTHON:-python3}"
[[ -x "$BENCH" ]] || { echo "soak: build process_bench first ($BENCH)" >&2; exit 1; }

hours=8 warp=100 vehicles=100 objects=100000 work=""
app_tick=4
while [[ $# -gt 0 && "$1" != "--" ]]; do
  case "$1" in
    --hours=*) hours="${1#*=}" ;;
    --warp=*) warp="${1#*=}" ;;
    --vehicles=*) vehicles="${1#*=}" ;;
    --objects=*) objects="${1#*=}" ;;
    --work-dir=*) work="${1#*=}" ;;
    *) echo "soak: unknown option '$1' (see the header of this script)" >&2; exit 1 ;;
  esac
  shift
done
[[ "${1:-}" == "--" ]] && shift
[[ -n "$work" ]] || work="$(mktemp -d /tmp/soak.XXXXXX)"
load_s=$("$PYTHON" -c "print(round($hours * 3600))")
eighth_s=$("$PYTHON" -c "print($load_s / 8)")

echo "soak: $vehicles vehicles, $objects objects, $hours simulated h at warp $warp in $work" >&2
set +e
"$BENCH" --objects="$objects" --vehicles="$vehicles" --warp="$warp" --duration="$load_s" \
  --report-hz=1 --request-hz=1 --app-tick="$app_tick" --config-every=600 --classify-every=40 \
  --drain=120 --sample-every=60 --moosdb-log=db.alog --original=none --work-dir="$work" "$@"
bench_status=$?
set -e
"$PYTHON" "$HERE/check_soak.py" "$work/ours/samples.csv" "$work/ours/db.alog" \
  --app-tick="$app_tick" --warmup-s="$eighth_s" --window-s="$eighth_s" --load-s="$load_s"
check_status=$?
echo "soak: logs in $work" >&2
[[ $bench_status -eq 0 && $check_status -eq 0 ]]
