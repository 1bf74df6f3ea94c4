#!/usr/bin/env bash
# The scripted-vehicle comparison of docs/validation.md: our uFldHazardSensor and the original,
# each on the same scene through the same MOOSDB, then the tables.
#
#   bench/validation/run.sh --original=PATH [--moosdb=PATH] [--runs=N] [--lanes=N] [--warp=W]
#                           [--out-dir=DIR]
#
# --original  the original uFldHazardSensor (built from MOOS-IvP, outside this tree)
# --moosdb    the MOOSDB both sensors use (default: our moosdb-lite)
# --runs      independent runs per program (default 3): ours with random_seed = 1..N, the
#             original with seed_random = true (seeded from the clock: the runs start seconds
#             apart, so each has its own stream)
# --lanes     lanes per run (default 25: 5,000 passes per kind of object and run)
# --warp      MOOS time warp (default 20)
# --out-dir   where the result files and the runs' folders stay (default: a new /tmp folder)
# Before the runs, one control run per program at pd = 1 (4 lanes) checks the pass count and the
# swath's extent. BUILD_DIR (default build/release) is where pass_bench was built.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BENCH="${BUILD_DIR:-$ROOT/build/release}/bench/validation/pass_bench"
[[ -x "$BENCH" ]] || { echo "run.sh: build pass_bench first ($BENCH)" >&2; exit 1; }

original="" moosdb="" runs=3 lanes=25 warp=20 out=""
for arg in "$@"; do
  case "$arg" in
    --original=*) original="${arg#*=}" ;;
    --moosdb=*)   moosdb="${arg#*=}" ;;
    --runs=*)     runs="${arg#*=}" ;;
    --lanes=*)    lanes="${arg#*=}" ;;
    --warp=*)     warp="${arg#*=}" ;;
    --out-dir=*)  out="${arg#*=}" ;;
    -h|--help)    sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done
[[ -x "$original" ]] || { echo "run.sh: --original=PATH must name the original program" >&2; exit 2; }
[[ "$runs" =~ ^[1-9][0-9]?$ ]] || { echo "run.sh: --runs must be a whole number in [1, 99]" >&2; exit 2; }
[[ -n "$out" ]] || out="$(mktemp -d /tmp/validation.XXXXXX)"
mkdir -p "$out"
common=(--warp="$warp")
[[ -n "$moosdb" ]] && common+=(--moosdb="$moosdb")

play() {  # NAME ARGS...: one pass_bench run into $out/NAME.csv and $out/NAME/
  local name="$1"; shift
  echo "== $name" >&2
  "$BENCH" "${common[@]}" --out="$out/$name.csv" --work-dir="$out/$name" "$@"
}

play control-ours --pd=1 --lanes=4 --seed=1
play control-original --pd=1 --lanes=4 --seed=time --sensor="$original"
ours=() originals=()
for ((i = 1; i <= runs; i++)); do
  play "ours-$i" --lanes="$lanes" --seed="$i"
  ours+=("$out/ours-$i.csv")
  play "original-$i" --lanes="$lanes" --seed=time --sensor="$original"
  originals+=("$out/original-$i.csv")
done

echo "Results in $out"
echo
echo "Control (pd = 1):"
python3 "$HERE/validate.py" control --ours "$out/control-ours.csv" --original "$out/control-original.csv"
echo
python3 "$HERE/validate.py" scene --ours "${ours[@]}" --original "${originals[@]}"
