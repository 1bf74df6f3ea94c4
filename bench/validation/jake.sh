#!/usr/bin/env bash
# The original MOOS-IvP Jake mission (m10_jake: shoreside, archie, betty, pShare, the grader
# uFldHazardMetric) run headless, once with the original uFldHazardSensor and once with ours
# first on PATH, then the side-by-side table of docs/validation.md (jake_report.py).
#
#   bench/validation/jake.sh --moos-bin=DIR --mission=DIR [--warp=W] [--runs=N]
#                            [--port-base=P] [--timeout=S] [--out-dir=DIR]
#
# --moos-bin   the folder with MOOSDB, pAntler, pShare, pLogger, nsplug, uPokeDB and the
#              MOOS-IvP programs of the mission, the original uFldHazardSensor among them
# --mission    MOOS-IvP's ivp/missions/m10_jake (copied; the copy is changed, never the source)
# --warp       MOOS time warp (default 20)
# --runs       runs per program (default 1). Run 1 keeps the mission's seed_random = false; later
#              runs set seed_random = true in both programs (seeded from the clock)
# --port-base  MOOSDB ports P, P+1, P+2 and pShare ports P+300.. (default 29000)
# --timeout    MOOS seconds a run may take before it is stopped (default 7200)
# --out-dir    where the runs' folders stay (default: a new /tmp folder)
# BUILD_DIR (default build/release) is where our uFldHazardSensor was built.
#
# The copy differs from the mission in what a headless run needs: pMarineViewer and pRealm are
# not launched (no display), the ports are moved to --port-base, the survey lanes the mission
# writes for charlie and davis are given to archie and betty (as written, archie and betty have
# no survey and return at once), the vehicles find the shoreside's pShare at its localhost port
# instead of by multicast, the vehicles are launched as kayaks (launch.sh makes them UUVs, whose
# helm then has a depth domain and no depth behaviour and stays in all-stop with
# "MissingDecVars:depth"), the shoreside's pLogger logs the sensor's variables by name as well
# (wildcard logging misses each variable's first posting), and the deploy buttons are posted by
# uPokeDB.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OURS="${BUILD_DIR:-$ROOT/build/release}/src/apps/uFldHazardSensor/uFldHazardSensor"

bin="" mission="" warp=20 runs=1 base=29000 timeout=7200 out=""
for arg in "$@"; do
  case "$arg" in
    --moos-bin=*)  bin="${arg#*=}" ;;
    --mission=*)   mission="${arg#*=}" ;;
    --warp=*)      warp="${arg#*=}" ;;
    --runs=*)      runs="${arg#*=}" ;;
    --port-base=*) base="${arg#*=}" ;;
    --timeout=*)   timeout="${arg#*=}" ;;
    --out-dir=*)   out="${arg#*=}" ;;
    -h|--help)     sed -n '2,25p' "$0"; exit 0 ;;
    *) echo "jake.sh: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done
for program in MOOSDB pAntler pShare pLogger nsplug uPokeDB uFldHazardSensor; do
  [[ -x "$bin/$program" ]] || { echo "jake.sh: --moos-bin has no $program ($bin)" >&2; exit 2; }
done
[[ -f "$mission/meta_shoreside.moos" ]] || { echo "jake.sh: --mission has no meta_shoreside.moos" >&2; exit 2; }
[[ -x "$OURS" ]] || { echo "jake.sh: build our uFldHazardSensor first ($OURS)" >&2; exit 1; }
[[ "$runs" =~ ^[1-9]$ ]] || { echo "jake.sh: --runs must be in [1, 9]" >&2; exit 2; }
[[ "$base" =~ ^[0-9]+$ && "$base" -ge 1024 && "$base" -le 65000 ]] || { echo "jake.sh: --port-base must be in [1024, 65000]" >&2; exit 2; }
[[ "$warp" =~ ^[0-9]+$ && "$warp" -ge 1 && "$warp" -le 100 ]] || { echo "jake.sh: --warp must be a whole number in [1, 100]" >&2; exit 2; }
[[ -n "$out" ]] || out="$(mktemp -d /tmp/jake.XXXXXX)"
mkdir -p "$out"

# prepare DIR SEEDED: the mission copy with the headless changes, .moos and .bhv made by nsplug.
prepare() {
  local dir="$1" seeded="$2"
  cp -r "$mission/." "$dir/"
  (
    cd "$dir"
    sed -i -E '/Run *= *(pMarineViewer|pRealm)/d' meta_shoreside.moos meta_vehicle.moos
    sed -i -E "s/ServerPort *= *9000/ServerPort = $base/; s/localhost:9300/localhost:$((base + 300))/" meta_shoreside.moos
    sed -i -E 's/#ifdef VNAME charlie/#ifdef VNAME archie/; s/#elseifdef VNAME davis/#elseifdef VNAME betty/' meta_vehicle.bhv
    sed -i -E "s/pshare_route=multicast_9/pshare_route=localhost:$((base + 300))/" plug_uFldNodeBroker.moos
    # Wildcard logging registers a variable only after its first posting, which it misses.
    local logged="UHZ_CONFIG_REQUEST UHZ_CONFIG_ACK UHZ_CONFIG_ACK_ARCHIE UHZ_CONFIG_ACK_BETTY"
    logged+=" UHZ_DETECTION_REPORT UHZ_CLASSIFY_REQUEST UHZ_HAZARD_REPORT HAZARD_SEARCH_SCORE"
    logged+=" HAZARDSET_EVAL_ARCHIE HAZARDSET_EVAL_BETTY"
    for var in $logged; do sed -i -E "/WildCardLogging/i\\  Log = $var @ 0" plug_pLogger.moos; done
    [[ "$seeded" == yes ]] && sed -i -E 's/seed_random *= *false/seed_random = true/' meta_shoreside.moos
    PATH="$bin:$PATH" nsplug meta_shoreside.moos targ_shoreside.moos -f WARP="$warp" VNAME=shoreside HAZARD_FILE=hazards.txt
    local i=1
    for v in archie betty; do
      PATH="$bin:$PATH" nsplug meta_vehicle.moos "targ_$v.moos" -f WARP="$warp" VTYPE=KAYAK VNAME=$v \
        START_POS=0,0 VPORT=$((base + i)) SHARE_LISTEN=$((base + 300 + i))
      PATH="$bin:$PATH" nsplug meta_vehicle.bhv "targ_$v.bhv" -f VNAME=$v START_POS=0,0
      i=$((i + 1))
    done
  ) >"$dir/prepare.log" 2>&1
}

pgids=()
stop_all() {
  for g in "${pgids[@]}"; do kill -INT -- "-$g" 2>/dev/null || true; done
  sleep 3
  for g in "${pgids[@]}"; do kill -KILL -- "-$g" 2>/dev/null || true; done
  pgids=()
}
trap stop_all EXIT

shore_log() { find "$1" -name 'LOG_SHORESIDE*.alog' 2>/dev/null | head -1; }

# run DIR PATHPREFIX: launch the three communities, deploy, wait for both graded reports.
run() {
  local dir="$1" path="$2"
  (
    cd "$dir"
    for community in archie betty shoreside; do
      PATH="$path" setsid pAntler "targ_$community.moos" >"antler_$community.log" 2>&1 &
      echo $! >"antler_$community.pid"
      sleep 0.5
    done
  )
  for community in archie betty shoreside; do pgids+=("$(cat "$dir/antler_$community.pid")"); done
  sleep $((10))
  (cd "$dir" && PATH="$path" uPokeDB targ_shoreside.moos DEPLOY_ALL=true MOOS_MANUAL_OVERRIDE_ALL=false \
     RETURN_ALL=false HAZARD_SEARCH_START=true >poke.log 2>&1) || true
  local limit=$((timeout / warp + 30)) waited=0 log=""
  while ((waited < limit)); do
    log="$(shore_log "$dir")"
    if [[ -n "$log" ]] && grep -q 'HAZARDSET_EVAL_ARCHIE' "$log" && grep -q 'HAZARDSET_EVAL_BETTY' "$log"; then
      break
    fi
    sleep 2; waited=$((waited + 2))
  done
  (cd "$dir" && PATH="$path" uPokeDB targ_shoreside.moos \
     "APPCAST_REQ=node=shoreside,app=uFldHazardSensor,duration=5,key=jake,thresh=any" >>poke.log 2>&1) || true
  sleep 3
  stop_all
  ((waited < limit)) || echo "jake.sh: $dir: no graded report from both vehicles in $timeout MOOS s" >&2
}

runs_ours=() runs_original=()
for ((i = 1; i <= runs; i++)); do
  seeded=no; ((i > 1)) && seeded=yes
  for program in original ours; do
    dir="$out/$program-$i"
    rm -rf "$dir"; mkdir -p "$dir"
    prepare "$dir" "$seeded"
    if [[ $program == ours ]]; then
      mkdir -p "$dir/ours-bin"; ln -s "$OURS" "$dir/ours-bin/uFldHazardSensor"
      path="$dir/ours-bin:$bin:$PATH"
    else
      path="$bin:$PATH"
    fi
    echo "== $program run $i in $dir" >&2
    run "$dir" "$path"
    if [[ $program == ours ]]; then runs_ours+=("$dir"); else runs_original+=("$dir"); fi
  done
done
python3 "$HERE/jake_report.py" --ours "${runs_ours[@]}" --original "${runs_original[@]}"
