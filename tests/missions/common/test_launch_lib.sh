#!/usr/bin/env bash
# The launcher's end-of-mission rule (launch_lib.sh header, step "waits"): the mission ends once
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

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all checks passed"
