#pragma once
// hazard_replay --seeds=A..B --score: the metric's score of the report in the input.
//
// Contract: the grader is libmission's HazardMetric, configured from the mission file's
// `ProcessConfig = uFldHazardMetric` block line by line as uFldHazardMetric configures it
// (penalties, max_time, and hazard_file, read relative to the mission file: the ground truth;
// AppTick, CommsTick and the other MOOS application parameters are skipped, as the app does).
// The input's HAZARD_SEARCH_START and HAZARDSET_REPORT lines (what a shoreside pLogger records
// from the vehicles' pHazardMgr) up to the replay's end (the last input, or --until) are handed
// to it in time order, the grader starting at the first input's time, as uFldHazardMetric would
// have graded them live. The score is the last
// HAZARD_SEARCH_SCORE it posts (the value the MOOSDB holds at the end); none when the input
// holds no report the grader accepts. Configuration and run warnings go to the error stream,
// named "uFldHazardMetric: file:line: ...". A missing block or an unreadable hazard file is an
// error (exit status 1), named in `error`.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "hazard/driver.hpp"
#include "moos/mission.hpp"

namespace hazard_replay {

/// The block the grader is configured from.
inline constexpr const char* kMetricAppName = "uFldHazardMetric";

struct RecordedScore {
  std::optional<double> score;  ///< the last HAZARD_SEARCH_SCORE, if a report was graded
  std::string error;            ///< set: the grader could not be built
};

/// Grades the recorded reports in `mail` (time order) up to `end_s` against the mission's
/// metric block.
RecordedScore score_recorded_reports(const moos::MissionFile& mission,
                                     const std::vector<hazard::Mail>& mail, double end_s,
                                     std::ostream& err);

}  // namespace hazard_replay
