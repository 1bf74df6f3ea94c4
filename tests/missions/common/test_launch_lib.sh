#!/usr/bin/env bash
# The launcher's rules on synthetic input. The end of a mission (launch_lib.sh header, step
# "waits"): the mission ends once
# the grader has evaluated every final vehicle's report; a vehicle whose last report names no
# object is done after ML_EMPTY_REPORT_GRACE_S, and only that vehicle's own grace counts.
# Usage: test_launch_lib.sh path/to/launch_lib.sh
set -u
# shellcheck source=/dev/null
source "$1"

failures=0
check() {  # check NAME EXPECTED(0|1) COMMAND...
  local name="$1" expected="$2"
  shift 2
  "$@"
  local got=$?
  if [ "$got" -ne "$expected" ]; then
    echo "FAIL: $name (status $got, expected $expected)"
    failures=$((failures + 1))
  else
    echo "ok: $name"
  fi
}

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
ML_WATCH_FILE="$scratch/watch.out"
report() { printf '%s   HAZARDSET_REPORT     pHazardMgr_%s %s\n' "$1" "$2" "$3" >> "$ML_WATCH_FILE"; }
evaluation() { printf '%s   HAZARDSET_EVAL_%s     uFldHazardMetric x\n' "$1" "$2" >> "$ML_WATCH_FILE"; }

: > "$ML_WATCH_FILE"
report 1.0 deb 'source=deb#name=deb#x=1,y=2,label=3'
check "a report naming objects is not empty" 1 ml_last_report_is_empty deb
check "another vehicle has no report" 1 ml_last_report_is_empty de
report 2.0 deb 'source=deb#name=deb'
check "the last report decides: empty" 0 ml_last_report_is_empty deb
report 3.0 deb 'source=deb#name=deb#x=1,y=2,label=3'
check "the last report decides: not empty" 1 ml_last_report_is_empty deb

# A report naming objects waits for its evaluation, however long the grace has run.
ML_FINAL_VEHICLES=(deb)
ML_EMPTY_REPORT_GRACE_S=0
check "an unevaluated report keeps the mission going" 1 ml_mission_done
evaluation 4.0 DEB
check "the evaluation ends it" 0 ml_mission_done

# An empty report ends the wait after the grace, counted for that vehicle alone.
: > "$ML_WATCH_FILE"
ML_FINAL_VEHICLES=(abe deb)
ML_EMPTY_REPORT_GRACE_S=2
ML_EMPTY_SINCE=()
report 1.0 abe 'source=abe#name=abe'
report 1.0 deb 'source=deb#name=deb'
check "an empty report waits for the grace" 1 ml_mission_done
ML_EMPTY_SINCE[abe]=$(( $(date +%s) - 10 ))
check "one vehicle's grace does not end another's" 1 ml_mission_done
ML_EMPTY_SINCE[deb]=$(( $(date +%s) - 10 ))
check "both graces over: done" 0 ml_mission_done

# The processes come from the ANTLER block's Run lines, as pAntler reads them: the alias after
# '~' (else the binary's name), comments dropped, the launcher's own processes left out, and Run
# lines outside the block ignored.
cat > "$scratch/m.moos" <<'MOOS'
ServerPort = 9000
// Run = commented_out
ProcessConfig = ANTLER
{
  MSBetweenLaunches = 100
  Run = MOOSDB @ NewConsole = false
  Run = pLogLite @ NewConsole = false
  Run = pWebViewer @ NewConsole = false
  Run = uFldHazardSensor  @ NewConsole = false   // the sensor
  run = pHazardMgr @ NewConsole = false ~ pHazardMgr_abe
  Run=uSimSurveyVehicle~uSimSurveyVehicle_abe
  // Run = pNotMe @ NewConsole = false
}
ProcessConfig = uFldHazardSensor
{
  Run = not_a_process
}
MOOS
antler_expected="uFldHazardSensor uFldHazardSensor
pHazardMgr pHazardMgr_abe
uSimSurveyVehicle uSimSurveyVehicle_abe"
same_processes() { [ "$(ml_antler_processes "$scratch/m.moos")" = "$antler_expected" ]; }
check "the ANTLER block's Run lines, aliases and comments" 0 same_processes
unset ML_PROCESSES
ML_TEMPLATE="$scratch/m.moos"
read_three() { ml_read_processes && [ "${#ML_PROCESSES[@]}" -eq 3 ] && [ "${ML_PROCESSES[1]}" = "pHazardMgr pHazardMgr_abe" ]; }
check "ML_PROCESSES read from the mission file" 0 read_three
ML_PROCESSES=("a b")
keep_own() { ml_read_processes && [ "${#ML_PROCESSES[@]}" -eq 1 ]; }
check "a mission's own ML_PROCESSES is kept" 0 keep_own
jake_processes() {
  [ "$(ml_antler_processes "$(dirname "$1")/../jake/jake.moos" | wc -l)" -eq 6 ]
}
check "the Jake mission runs six processes besides the launcher's own" 0 jake_processes "$1"

# #include lines are spliced in, as nsplug and the programs read them: a relative path from the
# including file's folder, `<FILE>` or FILE, nested; a cycle or a missing file is an error.
mkdir -p "$scratch/plugs"
cat > "$scratch/with_include.moos" <<'MOOS'
ServerPort = $(PORT)
#include plugs/antler.moos
ProcessConfig = uFldHazardSensor
{
  random_seed = $(SEED)
}
MOOS
cat > "$scratch/plugs/antler.moos" <<'MOOS'
ProcessConfig = ANTLER
{
  Run = uFldHazardSensor @ NewConsole = false
#include <vehicles.moos>
}
MOOS
printf '  Run = pHazardMgr @ NewConsole = false ~ pHazardMgr_abe\n' > "$scratch/plugs/vehicles.moos"
included_processes() {
  [ "$(ml_antler_processes "$scratch/with_include.moos")" = "uFldHazardSensor uFldHazardSensor
pHazardMgr pHazardMgr_abe" ]
}
check "Run lines in #included files, nested, relative to the including file" 0 included_processes
plugged_include() {
  ml_plug "$scratch/with_include.moos" "$scratch/targ.moos" PORT=9001 SEED=4 &&
    grep -q '^  Run = pHazardMgr @ NewConsole = false ~ pHazardMgr_abe$' "$scratch/targ.moos" &&
    grep -q '^ServerPort = 9001$' "$scratch/targ.moos" && ! grep -q '#include' "$scratch/targ.moos"
}
check "the targ file has the included text and the values" 0 plugged_include
printf '#include ../with_cycle.moos\n' > "$scratch/plugs/back.moos"
printf 'ServerPort = 1\n#include plugs/back.moos\n' > "$scratch/with_cycle.moos"
cycle_named() { ml_expand_includes "$scratch/with_cycle.moos" 2>&1 >/dev/null | grep -q 'cycle'; }
check "an #include cycle is an error naming it" 0 cycle_named
check "an #include cycle fails" 1 ml_expand_includes "$scratch/with_cycle.moos"
printf 'ServerPort = 1\n#include nowhere.moos\n' > "$scratch/missing.moos"
missing_named() {
  ml_expand_includes "$scratch/missing.moos" 2>&1 >/dev/null | grep -q "missing.moos:2: cannot read .*nowhere.moos"
}
check "a missing #included file names the including line" 0 missing_named
check "a missing #included file fails" 1 ml_antler_processes "$scratch/missing.moos"

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all checks passed"
