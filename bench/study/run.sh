#!/usr/bin/env bash
# hazard_study's benchmark and the study of docs/study.md:
#   1. throughput: missions per CPU-minute on the Jake mission as written (throughput.py: user +
#      system time of nine hazard_study processes of 20 missions each; slowest, middle, fastest);
#   2. the study: the Jake mission over seeds 1..N for each setting below (sensor widths, and each
#      costly sensor effect switched off; docs/effects.md), fanned out with GNU parallel in
#      chunks of 50 seeds, CPU per mission measured per chunk; then tools/study_summary.py
#      prints the table and draws the plot.
#
#   bench/study/run.sh [N [JOBS]]      (default N = 1000 seeds per setting, JOBS = 2)
#
# BUILD_DIR names the build (default build/release). Finished chunks are kept: running it
# again with a larger N runs only the seeds that are missing.
# Output in runs/study/: <setting>.<chunk>.jsonl, cpu.json, study.md (the table), study.svg.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
n="${1:-1000}" jobs="${2:-2}"
study="${BUILD_DIR:-$repo/build/release}/src/apps/hazard_study/hazard_study"
mission="$repo/missions/jake/jake.moos"
out="$repo/runs/study"
mkdir -p "$out"

# 1. Throughput: the slowest, middle and fastest of nine runs of 20 missions.
python3 "$here/throughput.py" --runs=9 --seeds=20 --build="${BUILD_DIR:-$repo/build/release}" \
  | tee "$out/throughput.txt"

# 2. The settings: a name (file-safe) and its hazard_study options.
declare -A SET=(
  [archie_W25]=""
  [archie_W50]="--set=pHazardMgr_archie.swath_width=50 --set=uSimSurveyVehicle_archie.swath_width=50"
  [archie_W10]="--set=pHazardMgr_archie.swath_width=10 --set=uSimSurveyVehicle_archie.swath_width=10"
  [betty_W25]="--set=pHazardMgr_betty.swath_width=25"
  [speed_gate_off]="--set=uFldHazardSensor.max_vehicle_speed=off"
  [turn_blackout_off]="--set=uFldHazardSensor.max_turn_rate=off"
  [geodesy_off]="--set=uFldHazardSensor.geodesy=off"
  [swath_sweep_on]="--set=uFldHazardSensor.swath_sweep=true"
)
ORDER=(archie_W25 archie_W50 archie_W10 betty_W25 speed_gate_off turn_blackout_off geodesy_off swath_sweep_on)
chunk=50
tasks="$out/tasks.txt"
: > "$tasks"
# Chunk by chunk across the settings, so a study stopped early has the same seeds in each.
for ((first = 1; first <= n; first += chunk)); do
  last=$((first + chunk - 1 < n ? first + chunk - 1 : n))
  for name in "${ORDER[@]}"; do echo "$name $first $last" >> "$tasks"; done
done
export study mission out
run_chunk() {
  local name="$1" first="$2" last="$3"
  [ -s "$out/$name.$first.jsonl" ] && return 0
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U %S" -o "$out/$name.$first.time" \
    "$study" "$mission" --seeds="$first..$last" --setting="$name" ${SETS[$name]} > "$out/$name.$first.jsonl.part"
  mv "$out/$name.$first.jsonl.part" "$out/$name.$first.jsonl"
}
export -f run_chunk
# Bash cannot export an associative array: hand each chunk its options in the environment.
for name in "${ORDER[@]}"; do export "SET_$name=${SET[$name]}"; done
parallel -j "$jobs" --colsep ' ' \
  'declare -A SETS; v=SET_{1}; SETS[{1}]="${!v}"; run_chunk {1} {2} {3}' :::: "$tasks"

# CPU per mission per setting.
{
  echo "{"
  sep=""
  for name in "${ORDER[@]}"; do
    cpu=$(cat "$out/$name".*.time | awk '{ s += $1 + $2 } END { print s }')
    missions=$(cat "$out/$name".*.jsonl | wc -l)
    printf '%s  "%s": %s' "$sep" "$name" "$(awk -v c="$cpu" -v m="$missions" 'BEGIN { print c / m }')"
    sep=$',\n'
  done
  printf '\n}\n'
} > "$out/cpu.json"
files=()
for name in "${ORDER[@]}"; do files+=("$out/$name".*.jsonl); done
python3 "$repo/tools/study_summary.py" --cpu "$out/cpu.json" --svg "$out/study.svg" \
  --title "Jake mission: score over $n seeds per setting (hazard_study)" "${files[@]}" | tee "$out/study.md"
