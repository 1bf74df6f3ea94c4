#pragma once
// One whole mission in lockstep (moos/lockstep.hpp): the mission's apps on an in-process bus,
// each cycling at its AppTick in simulated time, mail delivered by moos::Database's rules.
//
// Contract:
// - The bus clock starts at ManualClock's default epoch, warp 1 (MOOS time is simulated time).
//   Every app is started at that instant, in Run-line order, and cycled in that order whenever
//   several are due together. `deploy_s` later the runner posts DEPLOY_ALL = true and
//   HAZARD_SEARCH_START = true (what missions/common/launch_lib.sh pokes once every process is
//   connected).
// - The mission ends (`end`) when every final vehicle's report was graded (a
//   HAZARDSET_EVAL_<VEHICLE> posting; "graded"), or its last HAZARDSET_REPORT names no object
//   (the grader evaluates none; "empty_report"), or at `max_time_s` after deployment
//   ("max_time").
// - The result counts UHZ_DETECTION_REPORT and UHZ_HAZARD_REPORT postings, keeps the last
//   HAZARD_SEARCH_SCORE and the last final vehicle's HAZARDSET_EVAL_<VEHICLE>.
// - Nothing depends on the wall clock, threads or the environment: the same plan, setting and
//   seed give the same result and the same log, byte for byte.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "field_cache.hpp"
#include "mission/messages/hazardset_eval.hpp"
#include "mission_plan.hpp"

namespace hazard_study {

struct MissionResult {
  std::string setting;
  std::optional<std::uint64_t> field_seed;  ///< a generated field's seed (set by the study)
  std::uint64_t seed = 0;
  std::string end;                   ///< "graded", "empty_report" or "max_time"
  std::optional<double> score;       ///< the last HAZARD_SEARCH_SCORE
  std::optional<mission::HazardsetEval> eval;  ///< the last final vehicle's evaluation
  long detections = 0;
  long classifications = 0;
  double sim_s = 0.0;                ///< simulated seconds from deployment to the end
  /// The apps' configuration warnings, "<process>: <text>" (run once per setting suffices).
  std::vector<std::string> config_warnings;
};

struct RunOptions {
  double deploy_s = 1.0;
  double max_time_s = 12000.0;
  /// The sensor's engine and the grader come from it (one load per field); nullptr: each app
  /// loads its hazard files itself.
  FieldCache* fields = nullptr;
};

/// Runs one mission. With `alog`, every posting is appended as an .alog (header first).
MissionResult run_mission(const MissionPlan& plan, const Setting& setting, std::uint64_t seed,
                          const RunOptions& options, std::string* alog = nullptr);

}  // namespace hazard_study
