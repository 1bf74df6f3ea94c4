#!/usr/bin/env bash
# The Jake mission live (missions/jake/launch.sh on moosdb-lite) against hazard_study in
# lockstep, over the same seeds; the two score samples compared by compare_live.py
# (docs/study.md "Equal to the live mission"). Not a CI test: the live runs take ~15 s each.
#
#   bench/study/live_compare.sh [FIRST LAST [WARP]]     (default seeds 1..30, warp 400)
#
# Two live missions at a time at most (the machine is shared); output in runs/live-compare/.
# The launcher finds the programs in build/release/src/apps; BUILD_DIR names another build for
# hazard_study.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
first="${1:-1}" last="${2:-30}" warp="${3:-400}"
out="$repo/runs/live-compare"
mkdir -p "$out"
study="${BUILD_DIR:-$repo/build/release}/src/apps/hazard_study/hazard_study"

seq "$first" "$last" | xargs -P 2 -I{} sh -c \
  "[ -f '$out/live-{}/summary.json' ] || '$repo/missions/jake/launch.sh' $warp --seed={} --no-view \
     --no-picture --quiet --run-dir='$out/live-{}' > '$out/live-{}.log' 2>&1 || true"
"$study" "$repo/missions/jake/jake.moos" --seeds="$first..$last" > "$out/lockstep.jsonl"
python3 "$here/compare_live.py" "$out" "$out/lockstep.jsonl"
