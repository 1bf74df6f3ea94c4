# shellcheck shell=bash
# The mission launcher's set-up (sourced by launch_lib.sh, which documents the variables): its
# command line (ml_usage, ml_parse_args), the mission's processes from the `Run =` lines of its
# `ProcessConfig = ANTLER` block (ml_antler_processes, ml_read_processes) and where their
# programs are (ml_find_binaries: --bin-dir, the source tree's build, or the PATH as pAntler
# looks them up).

ml_usage() {
  cat <<EOF
Usage: $0 [WARP] [OPTIONS]

$ML_TITLE
Runs the whole mission headless and ends with a score table and a picture.

  WARP, --warp=W     MOOS time warp, 0 < W <= $ML_MAX_WARP (default $ML_DEFAULT_WARP)
  --seed=N           the sensor's random_seed, a whole number (default $ML_DEFAULT_SEED)
  --moosdb=lite      run on moosdb-lite, which also writes the log (default)
  --moosdb=real      run on MOOS-IvP's MOOSDB (must be on the PATH); pLogLite writes the log
  --bin-dir=DIR      where the binaries are: DIR/<app>/<app> or DIR/<app>
                     (default: $(ml_default_bin_text))
  --runs-dir=DIR     parent of the run folder (default: $(ml_default_runs_dir))
  --run-dir=DIR      the run folder itself (created; must not exist or be empty)
  --timeout=S        give up after S real seconds (default: $ML_MAX_SIM_S simulated seconds
                     at the warp, plus $ML_TIME_LIMIT_SLACK_S s)
  --no-picture       skip the picture
EOF
  if [ -n "${ML_VIEWER:-}" ]; then
    cat <<EOF
  --view-port=PORT   the live view's port on 127.0.0.1 (default 0: a free port, printed)
  --no-view          no live view (pWebViewer) and no view.html
EOF
  fi
  cat <<EOF
  --quiet            no progress display
  --help, -h         this text
EOF
  if declare -F ml_extra_usage >/dev/null; then ml_extra_usage; fi
  cat <<EOF

The run folder gets the .alog of the whole run, summary.json (the grader's result),
the picture (SVG and PNG), targ_$ML_MISSION.moos, pids.txt and logs/ (each process's output)${ML_VIEWER:+,
and view.html (the whole run to replay in a browser)}.
Exit status: 0 graded; 1 the mission failed; 2 bad usage; 130 interrupted.
EOF
}

ml_default_runs_dir() {
  if [ -n "$ML_INSTALLED" ]; then printf '%s/runs' "$PWD"; else printf '%s/runs' "$ML_REPO"; fi
}

ml_default_bin_text() {
  if [ -n "$ML_INSTALLED" ]; then printf 'the PATH'; else printf 'build/release/src/apps of the source tree'; fi
}

# ml_expand_includes FILE: the file's text with each `#include FILE` or `#include <FILE>` line
# replaced by that file's text, recursively (a relative path is taken from the including file's
# folder), as nsplug writes a targ file and as the programs read a mission file. A file that
# cannot be read, a cycle or a chain deeper than 10 files is an error naming the file and line.
ml_expand_includes() {
  awk -v top="$1" '
    function folder(path) { if (path !~ /\//) return ""; sub(/[^\/]*$/, "", path); return path }
    function normal(path,    parts, n, i, out, k, kept) {  # a/./b/../c -> a/c
      n = split(path, parts, "/"); k = 0
      for (i = 1; i <= n; i++) {
        if (parts[i] == "." || (parts[i] == "" && i > 1)) continue
        if (parts[i] == ".." && k > 0 && kept[k] != ".." && kept[k] != "") { k--; continue }
        kept[++k] = parts[i]
      }
      out = kept[1]; for (i = 2; i <= k; i++) out = out "/" kept[i]
      return out
    }
    function fail(message) { print message > "/dev/stderr"; failed = 1; exit 1 }
    function expand(file, depth, from,    line, n, target, got, i) {
      if (depth > 10) fail(from ": #include nested deeper than 10 files")
      for (i = 1; i < depth; i++) if (stack[i] == file) fail(from ": #include cycle through " file)
      stack[depth] = file
      while ((got = (getline line < file)) > 0) {
        n++
        if (line !~ /^[ \t]*#include([ \t]|$)/) { print line; continue }
        target = line
        sub(/^[ \t]*#include[ \t]*/, "", target)
        sub(/[ \t]+$/, "", target)
        if (target ~ /^</) { if (target !~ />$/) fail(file ":" n ": #include <... has no closing >")
                             target = substr(target, 2, length(target) - 2) }
        if (target == "" || target ~ /[ \t]/) fail(file ":" n ": #include needs one file name")
        if (target !~ /^\//) target = normal(folder(file) target)
        expand(target, depth + 1, file ":" n)
      }
      if (got < 0) fail(from ": cannot read " file)
      close(file)
    }
    BEGIN { expand(normal(top), 1, top) }'
}

# ml_antler_processes FILE: "binary alias" for every `Run = binary @ ... ~ alias` line of the
# file's `ProcessConfig = ANTLER` block (included files spliced in; the alias defaults to the
# binary), in order, but the processes the launcher starts itself (ML_INFRASTRUCTURE).
ml_antler_processes() {
  local text
  text="$(ml_expand_includes "$1")" || return 1
  printf '%s\n' "$text" | awk -v skip=" ${ML_INFRASTRUCTURE[*]} " '
    { sub(/\/\/.*/, "") }
    /^[ \t]*ProcessConfig[ \t]*=[ \t]*ANTLER[ \t]*$/ { in_block = 1; next }
    in_block && /^[ \t]*}/ { in_block = 0 }
    in_block && /^[ \t]*[Rr][Uu][Nn][ \t]*=/ {
      line = $0
      sub(/^[^=]*=[ \t]*/, "", line)
      alias = ""
      if (index(line, "~") > 0) {
        alias = substr(line, index(line, "~") + 1)
        gsub(/[ \t]/, "", alias)
        line = substr(line, 1, index(line, "~") - 1)
      }
      sub(/@.*/, "", line)
      gsub(/[ \t]/, "", line)
      if (line == "" || index(skip, " " line " ") > 0) next
      print line, (alias == "" ? line : alias)
    }'
}

# ML_PROCESSES from the mission file's ANTLER block unless the mission lists them itself.
ml_read_processes() {
  declare -p ML_PROCESSES >/dev/null 2>&1 && [ "${#ML_PROCESSES[@]}" -gt 0 ] && return 0
  local line
  ML_PROCESSES=()
  local processes
  processes="$(ml_antler_processes "$ML_TEMPLATE")" ||
    { ml_say "$ML_TEMPLATE: the mission file cannot be read (above)"; exit 2; }
  while IFS= read -r line; do [ -n "$line" ] && ML_PROCESSES+=("$line"); done <<<"$processes"
  [ "${#ML_PROCESSES[@]}" -gt 0 ] ||
    { ml_say "$ML_TEMPLATE: no process to run (no Run line in its ProcessConfig = ANTLER block)"; exit 2; }
}

ml_is_number() { [[ "$1" =~ ^[0-9]+([.][0-9]*)?$|^[.][0-9]+$ ]]; }

ml_parse_args() {
  ML_WARP="$ML_DEFAULT_WARP"
  ML_SEED="$ML_DEFAULT_SEED"
  ML_MOOSDB=lite
  ML_BIN_DIR=""
  ML_RUNS_DIR="$(ml_default_runs_dir)"
  ML_RUN_DIR=""
  ML_TIMEOUT_S=""
  ML_PICTURE=1
  ML_PROGRESS=1
  ML_VIEW="${ML_VIEWER:-}"
  ML_VIEW_PORT=0
  local arg warp_given=""
  for arg in "$@"; do
    case "$arg" in
      -h|--help|-help) ml_usage; exit 0 ;;
      --warp=*) ML_WARP="${arg#*=}"; warp_given=1 ;;
      --seed=*) ML_SEED="${arg#*=}" ;;
      --moosdb=*) ML_MOOSDB="${arg#*=}" ;;
      --bin-dir=*) ML_BIN_DIR="${arg#*=}" ;;
      --runs-dir=*) ML_RUNS_DIR="${arg#*=}" ;;
      --run-dir=*) ML_RUN_DIR="${arg#*=}" ;;
      --timeout=*) ML_TIMEOUT_S="${arg#*=}" ;;
      --no-picture) ML_PICTURE="" ;;
      --quiet) ML_PROGRESS="" ;;
      --view-port=*) ML_VIEW_PORT="${arg#*=}" ;;
      --no-view) ML_VIEW="" ;;
      -*)
        if declare -F ml_extra_option >/dev/null && ml_extra_option "$arg"; then continue; fi
        ml_die_usage "unknown option '$arg'" ;;
      *)
        [ -z "$warp_given" ] || ml_die_usage "unexpected argument '$arg' (the warp is already $ML_WARP)"
        ML_WARP="$arg"; warp_given=1 ;;
    esac
  done
  ml_is_number "$ML_WARP" || ml_die_usage "the warp '$ML_WARP' is not a number"
  awk -v w="$ML_WARP" -v m="$ML_MAX_WARP" 'BEGIN { exit !(w > 0 && w <= m) }' ||
    ml_die_usage "the warp $ML_WARP is outside (0, $ML_MAX_WARP]"
  [[ "$ML_SEED" =~ ^[0-9]+$ ]] || ml_die_usage "the seed '$ML_SEED' is not a whole number"
  [[ "$ML_VIEW_PORT" =~ ^[0-9]+$ ]] && [ "$ML_VIEW_PORT" -le 65535 ] ||
    ml_die_usage "the view port '$ML_VIEW_PORT' is not a port number"
  case "$ML_MOOSDB" in lite|real) ;; *) ml_die_usage "--moosdb must be lite or real, not '$ML_MOOSDB'" ;; esac
  if [ -n "$ML_TIMEOUT_S" ]; then
    ml_is_number "$ML_TIMEOUT_S" || ml_die_usage "the timeout '$ML_TIMEOUT_S' is not a number"
  else
    ML_TIMEOUT_S=$(awk -v s="$ML_MAX_SIM_S" -v w="$ML_WARP" -v k="$ML_TIME_LIMIT_SLACK_S" \
                   'BEGIN { printf "%d", s / w + k }')
  fi
}

# ml_find_binary APP DIR: sets ML_BIN_<app> to DIR/APP/APP or DIR/APP (DIR empty: APP on the
# PATH, as pAntler finds it); false when there is none.
ml_find_binary() {
  local app="$1" dir="$2" candidate
  if [ -z "$dir" ]; then
    candidate="$(command -v -- "$app")" || return 1
    printf -v "ML_BIN_${app//-/_}" '%s' "$candidate"
    return 0
  fi
  for candidate in "$dir/$app/$app" "$dir/$app"; do
    if [ -f "$candidate" ] && [ -x "$candidate" ]; then
      printf -v "ML_BIN_${app//-/_}" '%s' "$(cd "$(dirname "$candidate")" && pwd)/$app"
      return 0
    fi
  done
  return 1
}

# ML_BIN_<app> = the binary of <app>, from --bin-dir, the release build or (installed) the PATH.
ml_find_binaries() {
  local dir app missing=()
  if [ -n "$ML_BIN_DIR" ]; then dir="$ML_BIN_DIR"
  elif [ -z "$ML_INSTALLED" ]; then dir="$ML_REPO/build/release/src/apps"
  else dir=""
  fi
  local apps=(moosdb-lite moos-cli)
  for arg in "${ML_PROCESSES[@]}"; do apps+=("${arg%% *}"); done
  [ "$ML_MOOSDB" = real ] && apps+=(pLogLite)
  apps+=("${ML_EXTRA_BINARIES[@]}")
  for app in "${apps[@]}"; do
    ml_find_binary "$app" "$dir" || missing+=("$app")
  done
  # The view is a convenience: a mission runs without it.
  if [ -n "$ML_VIEW" ] && ! ml_find_binary pWebViewer "$dir"; then
    ml_say "pWebViewer is not built: no live view (build it, or pass --no-view)"
    ML_VIEW=""
  fi
  if [ "${#missing[@]}" -gt 0 ]; then
    ml_say "missing programs: ${missing[*]} (looked in ${dir:-the PATH: $PATH})"
    if [ -n "$ML_INSTALLED" ]; then
      ml_say "put the folder that holds them on the PATH, or give --bin-dir=DIR"
    else
      ml_say "build them first (./build.sh build), or give --bin-dir=DIR"
    fi
    exit 2
  fi
  if [ "$ML_MOOSDB" = real ]; then
    ML_BIN_MOOSDB="$(command -v MOOSDB || true)"
    if [ -z "$ML_BIN_MOOSDB" ]; then
      ml_say "--moosdb=real needs MOOS-IvP's MOOSDB on the PATH, and there is none"
      ml_say "install MOOS-IvP (core-moos) and add its bin folder to PATH, or use --moosdb=lite"
      exit 2
    fi
  fi
  command -v python3 >/dev/null || { ml_say "python3 is needed for the summary and the picture"; exit 2; }
}
