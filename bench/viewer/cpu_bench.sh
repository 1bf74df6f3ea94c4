#!/usr/bin/env bash
# pWebViewer's CPU per simulated hour (docs/viewer.md "Benchmarks"): moosdb-lite at
# warp W, pWebViewer with CLIENTS event streams open (curl stands in for a browser that keeps
# up), and viewer_load posting 10 vehicles' NODE_REPORTs at 4 Hz plus VIEW_CIRCLE/VIEW_MARKER
# traffic for SIM simulated seconds. Prints the CPU seconds (user + system, from
# /proc/<pid>/stat) of pWebViewer and of moosdb-lite per simulated hour, measured over the load.
#
#   bench/viewer/cpu_bench.sh [BUILD_DIR] [--warp=50] [--sim-seconds=3600] [--vehicles=10]
#                             [--clients=1]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD="$HERE/../../build/release"
WARP=50 SIM=3600 VEHICLES=10 CLIENTS=1
for arg in "$@"; do
  case "$arg" in
    --warp=*) WARP="${arg#*=}" ;;
    --sim-seconds=*) SIM="${arg#*=}" ;;
    --vehicles=*) VEHICLES="${arg#*=}" ;;
    --clients=*) CLIENTS="${arg#*=}" ;;
    -*) echo "unknown option $arg" >&2; exit 2 ;;
    *) BUILD="$arg" ;;
  esac
done
APPS="$BUILD/src/apps"
cmake --build "$BUILD" --target moosdb-lite pWebViewer viewer_load >/dev/null

DIR="$(mktemp -d)"
PIDS=()
cleanup() {
  local pid
  for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$DIR"
}
trap cleanup EXIT

# utime + stime of a process, in seconds.
cpu_s() {
  local stat fields
  stat="$(cat "/proc/$1/stat")"
  read -r -a fields <<<"${stat##*) }"
  awk -v u="${fields[11]}" -v s="${fields[12]}" -v t="$(getconf CLK_TCK)" 'BEGIN { printf "%.3f", (u + s) / t }'
}

"$APPS/moosdb-lite/moosdb-lite" --moos_port=0 --port-file="$DIR/port" --moos_community=bench \
  --moos_time_warp="$WARP" 2>"$DIR/db.err" &
DB=$!; PIDS+=("$DB")
for _ in $(seq 100); do [ -s "$DIR/port" ] && break; sleep 0.05; done
PORT="$(cat "$DIR/port")"
cat >"$DIR/bench.moos" <<MOOS
ServerHost = localhost
ServerPort = $PORT
Community = bench
MOOSTimeWarp = $WARP
ProcessConfig = pWebViewer
{
  AppTick = 4
  http_port = 0
}
MOOS
"$APPS/pWebViewer/pWebViewer" "$DIR/bench.moos" --moos_tw_delay_factor=0 >"$DIR/viewer.out" 2>&1 &
VIEWER=$!; PIDS+=("$VIEWER")
for _ in $(seq 200); do grep -q 'serving http://' "$DIR/viewer.out" && break; sleep 0.05; done
# The address without the printed ?token= (reading the stream needs none).
URL="$(grep -o 'http://[^ ?]*' "$DIR/viewer.out" | head -n 1)"
for ((i = 0; i < CLIENTS; i++)); do
  curl -sN "${URL}events" >"$DIR/client$i.out" &
  PIDS+=("$!")
done
sleep 1

viewer0="$(cpu_s "$VIEWER")"; db0="$(cpu_s "$DB")"
"$BUILD/bench/viewer/viewer_load" --port="$PORT" --warp="$WARP" --vehicles="$VEHICLES" --sim-seconds="$SIM"
sleep 0.5
viewer1="$(cpu_s "$VIEWER")"; db1="$(cpu_s "$DB")"
events="$(grep -c '^data: ' "$DIR/client0.out" 2>/dev/null || echo 0)"

awk -v v0="$viewer0" -v v1="$viewer1" -v d0="$db0" -v d1="$db1" -v sim="$SIM" -v w="$WARP" \
    -v n="$VEHICLES" -v c="$CLIENTS" -v e="$events" 'BEGIN {
  printf "warp %g, %d vehicles, %g simulated s (%.1f real s), %d event stream(s) open\n", w, n, sim, sim / w, c
  printf "pWebViewer:  %.2f CPU s per simulated hour (%.2f CPU s measured)\n", (v1 - v0) * 3600 / sim, v1 - v0
  printf "moosdb-lite: %.2f CPU s per simulated hour (%.2f CPU s measured)\n", (d1 - d0) * 3600 / sim, d1 - d0
  printf "events received by the first stream: %d\n", e
}'
