#!/usr/bin/env bash
# The rows of the side-by-side table against the original, run with process_bench
# (docs/performance.md).
#
#   bench/process/run.sh [PRESET...] [-- PROCESS_BENCH_OPTIONS...]
#
# Presets (all at warp 50, 10 Hz node reports, AppTick 4, markers off unless said):
#   10k-1     10,000 objects x 1 vehicle
#   10k-10    10,000 objects x 10 vehicles
#   100k-10   100,000 objects x 10 vehicles
#   1M-100    1,000,000 objects x 100 vehicles
#   1M-idle   1,000,000 objects, no vehicle (the idle cost): once as the original iterates
#             (every AppTick slot), once with IdleAppTick = 0.1 (opt-in, docs/differences.md)
#   1M-markers 1,000,000 objects x 100 vehicles with show_hazards on (memory)
#   all       the four table rows (the default)
#   sweep     10k, 100k and 1M objects x 1, 10 and 100 vehicles at warp 10, 300 simulated s
#             each (the plot of docs/performance.md; add -- --csv=FILE to keep the figures)
# Options after -- go to every run, e.g. --duration=300, --original=PATH, --moosdb=PATH
# (a real MOOSDB: both sensors then use it). BUILD_DIR (default build/release) is where
# process_bench was built.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BENCH="${BUILD_DIR:-$ROOT/build/release}/bench/process/process_bench"
[[ -x "$BENCH" ]] || { echo "run.sh: build process_bench first ($BENCH)" >&2; exit 1; }

presets=()
while [[ $# -gt 0 && "$1" != "--" ]]; do presets+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
[[ ${#presets[@]} -eq 0 ]] && presets=(all)

run() {
  echo "== process_bench $*" >&2
  "$BENCH" --warp=50 "$@"
}

status=0
for preset in "${presets[@]}"; do
  case "$preset" in
    10k-1)      run --objects=10000 --vehicles=1 "$@" || status=$? ;;
    10k-10)     run --objects=10000 --vehicles=10 "$@" || status=$? ;;
    100k-10)    run --objects=100000 --vehicles=10 "$@" || status=$? ;;
    1M-100)     run --objects=1000000 --vehicles=100 "$@" || status=$? ;;
    1M-idle)    run --objects=1000000 --vehicles=0 "$@" || status=$?
                run --objects=1000000 --vehicles=0 --idle-app-tick=0.1 "$@" || status=$? ;;
    1M-markers) run --objects=1000000 --vehicles=100 --markers "$@" || status=$? ;;
    all)        "$0" 10k-1 10k-10 100k-10 1M-100 -- "$@" || status=$? ;;
    sweep)
      for objects in 10000 100000 1000000; do
        for vehicles in 1 10 100; do
          run --warp=10 --objects=$objects --vehicles=$vehicles --duration=300 "$@" || status=$?
        done
      done ;;
    *) echo "run.sh: unknown preset '$preset' (see the header of this script)" >&2; exit 1 ;;
  esac
done
exit "$status"
