#!/usr/bin/env bash
# The Jake mission (manual section 13), headless: archie surveys the region with the 25 m sensor
# setting, hands its detections to betty, who reacquires them with the 10 m setting; the grader
# scores both reports; the run ends with a score table and a picture. pWebViewer shows the run
# live in a browser (the URL is printed at the start) and writes view.html into the run folder.
#
#   missions/jake/launch.sh [WARP] [--seed=N] [--moosdb=lite|real] [--bin-dir=DIR]
#                           [--view-port=PORT] [--no-view] [--help]
#
# Everything else (run folder, processes, stopping, summary, picture): missions/common/launch_lib.sh
# and docs/missions.md.
set -u

ML_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ML_MISSION=jake
ML_TITLE="Jake mission (manual 13): archie searches, betty reacquires"
ML_TEMPLATE="$ML_DIR/jake.moos"
ML_FILES=("$ML_DIR/hazards.txt")
ML_HAZARD_FILE=hazards.txt
# The processes: the Run lines of the mission file's ProcessConfig = ANTLER block.
ML_FINAL_VEHICLES=(betty)
ML_DEFAULT_WARP=400
ML_DEFAULT_SEED=3
ML_MAX_SIM_S=12000
ML_RENDER_OPTIONS=(--benign-shape square)
ML_EXTRA_KEYS=()
ML_EXTRA_BINARIES=()
ML_VIEWER=1   # pWebViewer: the live view in a browser, and view.html after the run

# shellcheck source=../common/launch_lib.sh
source "$ML_DIR/../common/launch_lib.sh"
ml_main "$@"
