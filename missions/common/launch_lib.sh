# shellcheck shell=bash
# The mission launcher shared by missions/*/launch.sh (sourced, not run). A mission's launch.sh
# sets the variables below and calls ml_main "$@". See docs/missions.md.
#
# It runs from the source tree (missions/ beside CMakeLists.txt) or installed
# (PREFIX/share/hazardsensor/missions, by cmake --install or the Debian package).
#
# What it does, in order:
#   1. reads the command line (ml_usage) and the mission's processes from the `Run =` lines of
#      its `ProcessConfig = ANTLER` block, as pAntler does (ml_antler_processes); finds the
#      binaries by name: in --bin-dir=DIR, else in the source tree's build/release/src/apps, else
#      (installed) on the PATH, as pAntler finds them; with --moosdb=real checks that MOOSDB is
#      on the PATH;
#   2. makes the run folder (runs/<mission>-<timestamp>/ in the source tree, or in the current
#      folder when installed), copies the mission's files into it,
#      runs the mission's prepare hook (ml_prepare, optional), starts the MOOSDB (moosdb-lite on
#      a port the OS chooses, logging every posting to <mission>.alog; or MOOS-IvP's MOOSDB on a
#      free port, with pLogLite writing the same .alog), and writes targ_<mission>.moos, the
#      mission file with its #include lines spliced in and every $(NAME) filled in (as nsplug);
#   3. with ML_VIEWER set (and pWebViewer built), starts pWebViewer, the browser view, and prints
#      its URL with the run's token (?token=..., which the page's buttons need; the page is live
#      while the mission runs);
#      starts every process of the mission, waits until all of them are connected (DB_CLIENTS),
#      then pokes DEPLOY_ALL=true and HAZARD_SEARCH_START=true;
#   4. shows a one-line progress display (simulated time, detections, classifications) until
#      the grader has evaluated the report of every vehicle in ML_FINAL_VEHICLES (a vehicle whose
#      report has no objects gets no evaluation: its HAZARDSET_REPORT ends the wait instead);
#   5. stops every process (first the mission's, then the logger, then the MOOSDB, so the log is
#      complete), writes summary.json and the picture, prints the score table and the picture's
#      path; with the viewer, writes view.html (pWebViewer --export: the whole run in one file a
#      browser opens) and says how to replay the run.
# It stops everything, leaving no process behind, when the mission ends, on Ctrl-C (SIGINT),
# SIGTERM or SIGHUP, when any process dies, and at the time limit. Every process runs in its own
# session (setsid) with SIGKILL as its parent-death signal (setpriv --pdeathsig), so that even
# a launcher killed with SIGKILL takes its processes with it; the stop sends SIGTERM to each
# process group, waits, then SIGKILL. run folder/pids.txt lists "name pid" for the launcher
# itself (first line, name "launcher") and each process it started; programs.txt "name binary"
# for each process (the binary as found, e.g. on the PATH); exits.txt "name status" for
# each process once it has ended (0: a clean exit after SIGTERM; 128 + N: killed by signal N).
#
# Exit status: 0 the mission ended and was graded; 1 the mission failed (a process died, the
# time limit passed, or a process could not start); 2 a bad command line or a missing binary;
# 130 interrupted (SIGINT), 143 terminated (SIGTERM), 129 hung up (SIGHUP).
#
# Variables a mission sets before ml_main:
#   ML_MISSION          name: the run folder, the .alog and the community are named after it
#   ML_TITLE            title of the picture and the score table
#   ML_DIR              the mission's folder (holds ML_TEMPLATE and ML_FILES)
#   ML_TEMPLATE         the mission file with $(PORT), $(WARP), $(SEED) (and ML_EXTRA_KEYS)
#   ML_FILES            files copied into the run folder (array)
#   ML_HAZARD_FILE      the ground truth, in the run folder (for the summary and the picture)
#   ML_PROCESSES        optional: "binary alias" per process, in start order (array); by default
#                       the ANTLER block's Run lines but MOOSDB, pLogLite and pWebViewer, which
#                       the launcher starts itself
#   ML_FINAL_VEHICLES   vehicles whose graded report ends the mission (array)
#   ML_DEFAULT_WARP     time warp when none is given
#   ML_DEFAULT_SEED     the sensor's random_seed when --seed is not given
#   ML_MAX_SIM_S        simulated seconds the mission may take (the default time limit)
#   ML_RENDER_OPTIONS   extra options of tools/render_mission.py (array)
#   ML_EXTRA_KEYS       more KEY=value substitutions for the template (array, may be empty)
#   ML_EXTRA_BINARIES   programs the prepare hook needs (array, may be empty)
#   ML_VIEWER           non-empty: start pWebViewer (its block in ML_TEMPLATE; http_port may be
#                       $(VIEW_PORT), from --view-port, 0 = a free port) unless --no-view
# A mission may define ml_prepare (run in the run folder before the MOOSDB starts; the variables
# ML_BIN_<name> hold the binaries' paths), ml_extra_usage (more --help text) and
# ml_extra_option ARG (true when it took a command-line option of its own).

# The folder that holds missions/ and tools/: the source tree, or PREFIX/share/hazardsensor.
ML_REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
if [ -f "$ML_REPO/CMakeLists.txt" ]; then ML_INSTALLED=""; else ML_INSTALLED=1; fi
# Started by the launcher itself, whatever the ANTLER block says.
ML_INFRASTRUCTURE=(MOOSDB pLogLite pWebViewer)
ML_MAX_WARP=400               # the MOOS limit on MOOSTimeWarp
ML_CONNECT_TIMEOUT_S=30       # real seconds for every process to connect
ML_STOP_WAIT_S=5              # real seconds a process has to exit after SIGTERM
ML_POLL_S=0.25                # real seconds between checks of the running mission
ML_EMPTY_REPORT_GRACE_S=3     # real seconds an evaluation may take before an empty report ends it
ML_TIME_LIMIT_SLACK_S=120     # real seconds added to ML_MAX_SIM_S / warp for the time limit
ML_QUIET_PROGRESS_EVERY_S=10  # without a terminal, one progress line this often
# Every process gets libMOOS's switch for the pause after each packet sent: 0 instead of
# 0.2 ms x warp, so that at a high warp the node reports reach the sensor one by one and not in
# bursts of 0.2 x W^2 ms of simulated time (32 s at W = 400). See docs/missions.md.
ML_APP_SWITCHES=(--moos_tw_delay_factor=0)

ml_say() { printf '[%s] %s\n' "$ML_MISSION" "$*" >&2; }
ml_die_usage() { ml_say "$*"; ml_say "see: $0 --help"; exit 2; }

# The command line, the processes and their programs.
# shellcheck source=launch_setup.sh
source "$(dirname "${BASH_SOURCE[0]}")/launch_setup.sh"

ml_make_run_dir() {
  if [ -z "$ML_RUN_DIR" ]; then
    local stamp base n=1
    stamp="$(date +%Y%m%d-%H%M%S)"
    base="$ML_RUNS_DIR/$ML_MISSION-$stamp"
    ML_RUN_DIR="$base"
    while [ -e "$ML_RUN_DIR" ]; do n=$((n + 1)); ML_RUN_DIR="$base-$n"; done
  elif [ -e "$ML_RUN_DIR" ] && [ -n "$(ls -A "$ML_RUN_DIR" 2>/dev/null)" ]; then
    ml_die_usage "the run folder $ML_RUN_DIR exists and is not empty"
  fi
  mkdir -p "$ML_RUN_DIR/logs" || { ml_say "cannot create $ML_RUN_DIR"; exit 1; }
  ML_RUN_DIR="$(cd "$ML_RUN_DIR" && pwd)"
  local f
  for f in "${ML_FILES[@]}"; do cp "$f" "$ML_RUN_DIR/" || { ml_say "cannot copy $f"; exit 1; }; done
  printf 'launcher %s\n' "$$" >"$ML_RUN_DIR/pids.txt"
  ML_ALOG="$ML_RUN_DIR/$ML_MISSION.alog"
  ML_TARG="$ML_RUN_DIR/targ_$ML_MISSION.moos"
}

# ml_plug TEMPLATE OUT KEY=VALUE...: nsplug's #include splicing (ml_expand_includes) and $(KEY)
# substitution; a $(NAME) left over is an error.
ml_plug() {
  local template="$1" out="$2"; shift 2
  local text pair key
  text="$(ml_expand_includes "$template")" || return 1
  for pair in "$@"; do
    key="${pair%%=*}"
    text="${text//\$($key)/${pair#*=}}"
  done
  # $(NAME) inside a comment is left as it is (libMOOS drops comments before reading).
  if printf '%s\n' "$text" | sed 's|//.*||' | grep -q '\$('; then
    ml_say "$template: no value for $(printf '%s\n' "$text" | sed 's|//.*||' | grep -o '\$([A-Za-z0-9_]*)' | sort -u | tr '\n' ' ')"
    return 1
  fi
  printf '%s\n' "$text" >"$out"
}

# ---- processes ------------------------------------------------------------------------------

ML_NAMES=()
ML_PIDS=()
ML_ENDED=()   # index -> 1 once the process has ended and its status is recorded
ML_PDEATH=()
if setpriv --help 2>/dev/null | grep -q -- --pdeathsig; then ML_PDEATH=(setpriv --pdeathsig KILL --); fi

# ml_spawn NAME COMMAND...: starts COMMAND in the run folder in its own session.
ml_spawn() {
  local name="$1"; shift
  setsid "${ML_PDEATH[@]}" "$@" >"$ML_RUN_DIR/logs/$name.out" 2>"$ML_RUN_DIR/logs/$name.err" </dev/null &
  local pid=$!
  ML_NAMES+=("$name")
  ML_PIDS+=("$pid")
  printf '%s %s\n' "$name" "$pid" >>"$ML_RUN_DIR/pids.txt"
  printf '%s %s\n' "$name" "$1" >>"$ML_RUN_DIR/programs.txt"
}

ml_alive() { kill -0 "$1" 2>/dev/null; }

# ml_stop_group FIRST LAST: SIGTERM to processes FIRST..LAST (indices), wait, then SIGKILL.
ml_stop_group() {
  local first="$1" last="$2" i deadline
  for ((i = first; i <= last; i++)); do
    [ -n "${ML_ENDED[i]:-}" ] && continue
    kill -TERM -- "-${ML_PIDS[i]}" 2>/dev/null || kill -TERM "${ML_PIDS[i]}" 2>/dev/null
  done
  deadline=$(( $(date +%s) + ML_STOP_WAIT_S ))
  for ((i = first; i <= last; i++)); do
    [ -n "${ML_ENDED[i]:-}" ] && continue
    while ml_alive "${ML_PIDS[i]}" && [ "$(date +%s)" -lt "$deadline" ]; do sleep 0.05; done
    if ml_alive "${ML_PIDS[i]}"; then
      ml_say "${ML_NAMES[i]} did not stop after SIGTERM; killing it"
      kill -KILL -- "-${ML_PIDS[i]}" 2>/dev/null || kill -KILL "${ML_PIDS[i]}" 2>/dev/null
    fi
    ml_record_exit "$i"
  done
}

# Appends "name status" to exits.txt once the process has ended (reaps it).
ml_record_exit() {
  local status=0
  wait "${ML_PIDS[$1]}" 2>/dev/null || status=$?
  printf '%s %s\n' "${ML_NAMES[$1]}" "$status" >>"$ML_RUN_DIR/exits.txt"
  ML_LAST_STATUS="$status"
  ML_ENDED[$1]=1
}

# Writes cpu.txt: "name user_s system_s" per process still running (from /proc; Linux only).
ml_record_cpu() {
  local tck i stat fields
  tck="$(getconf CLK_TCK 2>/dev/null || echo 100)"
  : >"$ML_RUN_DIR/cpu.txt"
  for i in "${!ML_PIDS[@]}"; do
    stat="$(cat "/proc/${ML_PIDS[i]}/stat" 2>/dev/null)" || continue
    # Fields after the ")" that ends the command name: utime and stime are the 12th and 13th.
    read -r -a fields <<<"${stat##*) }"
    awk -v n="${ML_NAMES[i]}" -v u="${fields[11]}" -v s="${fields[12]}" -v t="$tck" \
      'BEGIN { printf "%s %.2f %.2f\n", n, u / t, s / t }' >>"$ML_RUN_DIR/cpu.txt"
  done
}

# Stops everything: the mission's processes, then the logger, then the MOOSDB (ML_N_INFRA is the
# number of processes started before the mission's: the MOOSDB and, with a real MOOSDB, pLogLite).
ml_stop_all() {
  local n="${#ML_PIDS[@]}" i
  [ "$n" -gt 0 ] || return 0
  if [ "$n" -gt "${ML_N_INFRA:-0}" ]; then ml_stop_group "${ML_N_INFRA:-0}" $((n - 1)); fi
  for ((i = ${ML_N_INFRA:-0} - 1; i >= 0; i--)); do ml_stop_group "$i" "$i"; done
  ML_PIDS=()
  ML_NAMES=()
  ML_ENDED=()
}

ml_on_signal() {
  local code="$1" what="$2"
  trap '' INT TERM HUP
  ml_break_progress_line
  ml_say "$what: stopping every process"
  ml_stop_all
  ml_say "stopped; the run folder is $ML_RUN_DIR"
  exit "$code"
}

# ---- the MOOSDB ------------------------------------------------------------------------------

ml_free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

ml_wait_until() {  # ml_wait_until SECONDS COMMAND...: true once COMMAND succeeds
  local deadline=$(( $(date +%s) + $1 )); shift
  until "$@"; do
    [ "$(date +%s)" -lt "$deadline" ] || return 1
    ml_check_processes || return 1
    sleep 0.05
  done
}

ml_port_listening() { (exec 3<>"/dev/tcp/127.0.0.1/$ML_PORT") 2>/dev/null; }
ml_port_file_ready() { [ -s "$ML_RUN_DIR/logs/port" ]; }

ml_start_moosdb() {
  local plug=(WARP="$ML_WARP" SEED="$ML_SEED" VIEW_PORT="$ML_VIEW_PORT" "${ML_EXTRA_KEYS[@]}")
  if [ "$ML_MOOSDB" = lite ]; then
    ml_spawn moosdb-lite "$ML_BIN_moosdb_lite" --moos_port=0 --port-file="$ML_RUN_DIR/logs/port" \
      --moos_community="$ML_MISSION" --moos_time_warp="$ML_WARP" --log="$ML_ALOG"
    ML_N_INFRA=1
    ml_wait_until 10 ml_port_file_ready || { ml_say "moosdb-lite did not start (see logs/moosdb-lite.err)"; return 1; }
    ML_PORT="$(cat "$ML_RUN_DIR/logs/port")"
    ml_plug "$ML_TEMPLATE" "$ML_TARG" PORT="$ML_PORT" "${plug[@]}" || return 1
  else
    ML_PORT="$(ml_free_port)" || { ml_say "cannot find a free TCP port"; return 1; }
    ml_plug "$ML_TEMPLATE" "$ML_TARG" PORT="$ML_PORT" "${plug[@]}" || return 1
    ml_spawn MOOSDB "$ML_BIN_MOOSDB" "$ML_TARG"
    ml_wait_until 10 ml_port_listening || { ml_say "MOOSDB did not start on port $ML_PORT (see logs/MOOSDB.err)"; return 1; }
    ml_spawn pLogLite "$ML_BIN_pLogLite" "$ML_TARG" pLogLite "${ML_APP_SWITCHES[@]}"
    ML_N_INFRA=2
  fi
}

# ---- the view ---------------------------------------------------------------------------------

ml_viewer_ready() { grep -q 'serving http://' "$ML_RUN_DIR/logs/pWebViewer.out" 2>/dev/null; }

# Starts pWebViewer after the MOOSDB (so it hears the mission from its first posting; stopped
# with the MOOSDB's group, before it) and prints the URL once it listens.
ml_start_viewer() {
  [ -n "$ML_VIEW" ] || return 0
  ml_spawn pWebViewer "$ML_BIN_pWebViewer" "$ML_TARG" pWebViewer "${ML_APP_SWITCHES[@]}"
  ML_N_INFRA=$((ML_N_INFRA + 1))
  ml_wait_until 15 ml_viewer_ready || { ml_say "pWebViewer did not start (see logs/pWebViewer.err)"; return 1; }
  ML_VIEW_URL="$(grep -o 'http://[^ ]*' "$ML_RUN_DIR/logs/pWebViewer.out" | head -n 1)"
  ml_say "live view: $ML_VIEW_URL (open it in a browser while the mission runs)"
}

# After the run: the whole run as one HTML file, and how to replay it.
ml_export_view() {
  [ -n "$ML_VIEW" ] || return 0
  if "$ML_BIN_pWebViewer" "$ML_TARG" --export="$ML_ALOG" --output="$ML_RUN_DIR/view.html" \
       >"$ML_RUN_DIR/logs/view-export.out" 2>"$ML_RUN_DIR/logs/view-export.err"; then
    printf 'View: %s (open it in a browser; or replay: %s %s --replay=%s)\n' \
      "$ML_RUN_DIR/view.html" "$ML_BIN_pWebViewer" "$ML_TARG" "$ML_ALOG"
  else
    ml_say "writing view.html failed (see logs/view-export.err)"
  fi
}

# ---- the mission's processes -----------------------------------------------------------------

ml_cli() { "$ML_BIN_moos_cli" "$1" --port="$ML_PORT" --moos_time_warp="$ML_WARP" "${@:2}"; }

# True when DB_CLIENTS lists every name given.
ml_clients_connected() {
  local clients name
  clients="$(ml_cli watch --timeout=2 --count=1 --name="launch-$$-$RANDOM" DB_CLIENTS 2>/dev/null |
             awk 'END { print $4 }')"
  for name in "$@"; do
    [[ ",$clients," == *",$name,"* ]] || return 1
  done
}

ml_start_mission() {
  local entry binary alias names=()
  [ "$ML_MOOSDB" = real ] && names+=(pLogLite)
  for entry in "${ML_PROCESSES[@]}"; do
    binary="${entry%% *}"
    alias="${entry#* }"
    local var="ML_BIN_${binary//-/_}"
    ml_spawn "$alias" "${!var}" "$ML_TARG" "$alias" "${ML_APP_SWITCHES[@]}"
    names+=("$alias")
  done
  if ! ml_wait_until "$ML_CONNECT_TIMEOUT_S" ml_clients_connected "${names[@]}"; then
    ml_say "not every process connected within $ML_CONNECT_TIMEOUT_S s (see $ML_RUN_DIR/logs)"
    return 1
  fi
  # A watcher for the progress display and the end of the mission (few, small messages).
  ml_spawn progress-watch "$ML_BIN_moos_cli" watch --port="$ML_PORT" --moos_time_warp="$ML_WARP" \
    --name="mission-progress-$$" --timeout="$(( ${ML_TIMEOUT_S%.*} + 60 ))" \
    UHZ_DETECTION_REPORT UHZ_HAZARD_REPORT \
    HAZARDSET_REPORT 'HAZARDSET_EVAL_*'
  ML_WATCH_FILE="$ML_RUN_DIR/logs/progress-watch.out"
  ml_wait_until 10 ml_clients_connected "mission-progress-$$" ||
    { ml_say "the progress watcher did not connect"; return 1; }
  ml_cli poke --name="launch-deploy-$$" DEPLOY_ALL=true HAZARD_SEARCH_START=true >/dev/null ||
    { ml_say "cannot post DEPLOY_ALL"; return 1; }
  ML_DEPLOY_REAL_S="$(date +%s.%N)"
}

# False (with a message) when a process has died.
ml_check_processes() {
  local i
  for i in "${!ML_PIDS[@]}"; do
    if ! ml_alive "${ML_PIDS[i]}"; then
      ml_record_exit "$i"
      local status="${ML_LAST_STATUS}"
      ml_break_progress_line
      ml_say "${ML_NAMES[i]} (pid ${ML_PIDS[i]}) exited with status $status; see $ML_RUN_DIR/logs/${ML_NAMES[i]}.err"
      ML_FAILED_PROCESS="${ML_NAMES[i]}"
      return 1
    fi
  done
}

ml_count() { grep -c " $1 " "$ML_WATCH_FILE" 2>/dev/null || true; }

# True when the last HAZARDSET_REPORT of vehicle $1 names no object (the grader evaluates only
# reports that do, see the header).
ml_last_report_is_empty() {
  grep " HAZARDSET_REPORT .*source=$1\(#\|\$\)" "$ML_WATCH_FILE" 2>/dev/null | tail -n 1 |
    grep -q -v "label="
}

# When each final vehicle's empty report was first seen (real seconds), for the grace period.
declare -A ML_EMPTY_SINCE=()

# True once every final vehicle's report was evaluated (or reported empty, see the header).
ml_mission_done() {
  local v upper
  for v in "${ML_FINAL_VEHICLES[@]}"; do
    upper="$(printf '%s' "$v" | tr '[:lower:]' '[:upper:]')"
    grep -q " HAZARDSET_EVAL_$upper " "$ML_WATCH_FILE" 2>/dev/null && continue
    if ml_last_report_is_empty "$v"; then
      : "${ML_EMPTY_SINCE[$v]:=$(date +%s)}"
      [ $(( $(date +%s) - ML_EMPTY_SINCE[$v] )) -ge "$ML_EMPTY_REPORT_GRACE_S" ] && continue
    fi
    return 1
  done
}

# Ends the progress display's line (if one is shown) so that a message starts on its own line.
ml_break_progress_line() {
  if [ -n "${ML_PROGRESS_SHOWN:-}" ]; then printf '\n' >&2; fi
}

ml_progress_line() {
  local now sim
  now="$(date +%s.%N)"
  sim=$(awk -v a="$ML_DEPLOY_REAL_S" -v b="$now" -v w="$ML_WARP" 'BEGIN { printf "%d", (b - a) * w }')
  printf '[%s] sim %6s s  x%s  detections %3s  classifications %3s  reports %s' \
    "$ML_MISSION" "$sim" "$ML_WARP" "$(ml_count UHZ_DETECTION_REPORT)" \
    "$(ml_count UHZ_HAZARD_REPORT)" "$(ml_count HAZARDSET_REPORT)"
}

ml_run_until_done() {
  local start last_quiet=0 now
  start="$(date +%s)"
  while ! ml_mission_done; do
    ml_check_processes || return 1
    now="$(date +%s)"
    if [ $((now - start)) -ge "${ML_TIMEOUT_S%.*}" ]; then
      ml_break_progress_line
      ml_say "time limit of $ML_TIMEOUT_S s reached before the mission ended"
      return 1
    fi
    if [ -n "$ML_PROGRESS" ]; then
      if [ -t 2 ]; then
        printf '\r%s ' "$(ml_progress_line)" >&2
        ML_PROGRESS_SHOWN=1
      elif [ $((now - last_quiet)) -ge "$ML_QUIET_PROGRESS_EVERY_S" ]; then
        ml_progress_line >&2; printf '\n' >&2
        last_quiet="$now"
      fi
    fi
    sleep "$ML_POLL_S"
  done
  if [ -n "$ML_PROGRESS" ]; then
    if [ -t 2 ]; then printf '\r%s\n' "$(ml_progress_line)" >&2; else ml_progress_line >&2; printf '\n' >&2; fi
  fi
  ML_PROGRESS_SHOWN=""
  ML_END_REAL_S="$(date +%s.%N)"
}

# ---- the end ---------------------------------------------------------------------------------

ml_finish() {
  local real_s
  real_s=$(awk -v a="$ML_START_REAL_S" -v b="$ML_END_REAL_S" 'BEGIN { printf "%.1f", b - a }')
  python3 "$ML_REPO/missions/common/mission_summary.py" --alog "$ML_ALOG" \
    --hazards "$ML_RUN_DIR/$ML_HAZARD_FILE" --out "$ML_RUN_DIR/summary.json" --title "$ML_TITLE" \
    --mission "$ML_MISSION" --seed "$ML_SEED" --warp "$ML_WARP" --moosdb "$ML_MOOSDB" \
    --real-seconds "$real_s" --cpu "$ML_RUN_DIR/cpu.txt" --final "${ML_FINAL_VEHICLES[@]}" || return 1
  if [ -n "$ML_PICTURE" ]; then
    python3 "$ML_REPO/tools/render_mission.py" --alog "$ML_ALOG" \
      --hazards "$ML_RUN_DIR/$ML_HAZARD_FILE" --summary "$ML_RUN_DIR/summary.json" \
      --svg "$ML_RUN_DIR/$ML_MISSION.svg" --png "$ML_RUN_DIR/$ML_MISSION.png" \
      "${ML_RENDER_OPTIONS[@]}" 2>"$ML_RUN_DIR/logs/render.err" ||
      { ml_say "the picture failed (see logs/render.err)"; return 1; }
    if [ -f "$ML_RUN_DIR/$ML_MISSION.png" ]; then
      printf 'Picture: %s\n' "$ML_RUN_DIR/$ML_MISSION.png"
    else
      printf 'Picture: %s (no PNG: rsvg-convert is not installed)\n' "$ML_RUN_DIR/$ML_MISSION.svg"
    fi
  fi
  printf 'Run folder: %s\n' "$ML_RUN_DIR"
}

ml_main() {
  ml_parse_args "$@"
  ml_read_processes
  ml_find_binaries
  ml_make_run_dir
  cd "$ML_RUN_DIR" || exit 1
  trap 'ml_on_signal 130 interrupted' INT
  trap 'ml_on_signal 143 terminated' TERM
  trap 'ml_on_signal 129 "hung up"' HUP
  ML_START_REAL_S="$(date +%s.%N)"
  ml_say "run folder $ML_RUN_DIR (warp $ML_WARP, seed $ML_SEED, MOOSDB $ML_MOOSDB)"
  if declare -F ml_prepare >/dev/null; then ml_prepare || { ml_say "preparing the mission failed"; exit 1; }; fi
  local ok=1
  ml_start_moosdb || ok=""
  if [ -n "$ok" ]; then ml_start_viewer || ok=""; fi
  if [ -n "$ok" ]; then ml_start_mission || ok=""; fi
  if [ -n "$ok" ]; then ml_run_until_done || ok=""; fi
  trap '' INT TERM HUP
  ml_record_cpu
  ml_stop_all
  trap - INT TERM HUP
  if [ -z "$ok" ]; then
    ml_say "the mission failed; the run folder is $ML_RUN_DIR"
    exit 1
  fi
  ml_finish || exit 1
  ml_export_view
}
