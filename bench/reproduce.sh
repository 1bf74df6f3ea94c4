#!/usr/bin/env bash
# Reproduces every number in docs/effects.md, docs/accuracy.md, docs/performance.md and
# docs/study.md and redraws docs/images/accuracy.svg, docs/images/performance.svg and
# docs/images/study.svg.
#
#   bench/reproduce.sh [BUILD_DIR]      BUILD_DIR: a Release build (default build/release)
#
# Timings are ratios measured in one run; absolute microseconds depend on the machine and on
# what else runs on it (run on an idle machine).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/.." && pwd)"
BUILD="${1:-$ROOT/build/release}"

cmake --build "$BUILD" --target effects_bench scale_bench hazard_replay gen_hazards accuracy_bench \
  moosdb_bench process_bench hazard_study -j2 >&2
echo "# docs/effects.md"
"$BUILD/bench/engine/effects_bench"
echo
echo "# docs/accuracy.md"
DATA="$(mktemp -d)"
trap 'rm -rf "$DATA"' EXIT
"$BUILD/bench/accuracy/accuracy_bench" --csv "$DATA"
python3 "$HERE/accuracy/plot_accuracy.py" "$DATA" "$ROOT/docs/images/accuracy.svg"
echo "(plot: docs/images/accuracy.svg)" >&2
echo
echo "# docs/performance.md (about ten minutes; a reference MOOSDB or original"
echo "# uFldHazardSensor on PATH is measured side by side)"
"$BUILD/bench/engine/scale_bench"
BUILD_DIR="$BUILD" "$HERE/engine/replay_rate.sh" 120
"$BUILD/bench/moosdb/moosdb_bench"
BUILD_DIR="$BUILD" "$HERE/process/run.sh" all 1M-idle
BUILD_DIR="$BUILD" "$HERE/process/run.sh" 1M-markers -- --duration=300
BUILD_DIR="$BUILD" "$HERE/process/run.sh" sweep -- --csv="$DATA/performance.csv"
python3 "$HERE/process/plot_performance.py" "$DATA/performance.csv" "$ROOT/docs/images/performance.svg"
echo "(plot: docs/images/performance.svg)" >&2
echo
echo "# docs/study.md (1,000 seeds per setting: about an hour of CPU; the live comparison is"
echo "# bench/study/live_compare.sh, run by hand)"
BUILD_DIR="$BUILD" "$HERE/study/run.sh" 1000 2
cp "$ROOT/runs/study/study.svg" "$ROOT/docs/images/study.svg"
echo "(plot: docs/images/study.svg)" >&2
