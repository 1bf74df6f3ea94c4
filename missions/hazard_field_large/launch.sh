#!/usr/bin/env bash
# A large hazard field, headless: 10,000 objects over 3 km x 3 km (gen_hazards, fixed seed),
# four vehicles surveying parallel strips at once at a high time warp; abe, ben and cal hand
# their detections to deb, whose report is the fleet's answer. Ends with a score table and a
# picture, like missions/jake.
#
#   missions/hazard_field_large/launch.sh [WARP] [--seed=N] [--field-seed=N] [--moosdb=lite|real]
#                                         [--bin-dir=DIR] [--help]
#
# Everything else: missions/common/launch_lib.sh and docs/missions.md.
set -u

ML_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ML_MISSION=hazard_field_large
ML_TITLE="Large hazard field: 10,000 objects, 3 km x 3 km, four vehicles"
ML_TEMPLATE="$ML_DIR/hazard_field_large.moos"
ML_FILES=()
ML_HAZARD_FILE=hazards.txt
# The processes: the Run lines of the mission file's ProcessConfig = ANTLER block.
ML_FINAL_VEHICLES=(deb)
ML_DEFAULT_WARP=400
ML_DEFAULT_SEED=1
ML_MAX_SIM_S=30000
ML_RENDER_OPTIONS=(--benign-shape square)
ML_EXTRA_KEYS=()
ML_EXTRA_BINARIES=(gen_hazards)

# The field: the same file for a given --field-seed on every machine (gen_hazards promises it).
FIELD_SEED=2026
FIELD_REGION=0,0:3000,0:3000,-3000:0,-3000
FIELD_OBJECTS=(--objects=2000,hazard --objects=8000,benign)

ml_extra_usage() {
  cat <<EOF2
  --field-seed=N     gen_hazards seed of the field (default $FIELD_SEED)
EOF2
}

ml_extra_option() {
  case "$1" in
    --field-seed=*)
      FIELD_SEED="${1#*=}"
      [[ "$FIELD_SEED" =~ ^[0-9]+$ ]] || ml_die_usage "the field seed '$FIELD_SEED' is not a whole number"
      return 0 ;;
  esac
  return 1
}

ml_prepare() {
  "$ML_BIN_gen_hazards" --polygon="$FIELD_REGION" "${FIELD_OBJECTS[@]}" --seed="$FIELD_SEED" \
    --output="$ML_RUN_DIR/$ML_HAZARD_FILE"
}

# shellcheck source=../common/launch_lib.sh
source "$ML_DIR/../common/launch_lib.sh"
ml_main "$@"
