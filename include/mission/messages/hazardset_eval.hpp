#pragma once
// HAZARDSET_EVAL, HAZARDSET_EVAL_<SRC>, HAZARDSET_EVAL_FULL, HAZARDSET_EVAL_FULL_<SRC>
// (docs/mission-logic.md): the grader's verdict on one HAZARDSET_REPORT.
//
// Example (short, one line):
//   vname=archie,report_name=archie,total_score=20,norm_score=86.67,score_missed_hazards=0,
//   score_false_alarms=20,score_time_overage=0,total_objects=7,total_time=0,received_time=812.5,
//   start_time=0,missed_hazards=0,correct_hazards=5,false_alarms=2,penalty_false_alarm=10,
//   penalty_missed_hazard=100,penalty_max_time_over=0,penalty_max_time_rate=0,max_time=0
// The full form appends
//   ,object_report={label=75,truth=hazard,report=hazard#label=82,truth=benign,report=hazard,
//   penalty=10#...}
// Key order as above; report_name only when non-empty; total_score, norm_score,
// score_time_overage FMT(.,2); counts as integers; every other number FMT(.,5); penalty in the
// object report FMT(.,2), present for a missed hazard and for a false alarm.
//
// Parsing accepts both forms, keys case-insensitive; a count that is not a whole number >= 0 or a
// number field that is not a number is an error naming key and value; unknown keys are ignored.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hazard/messages/parsed.hpp"

namespace mission {

inline constexpr const char* kHazardsetEvalVar = "HAZARDSET_EVAL";
inline constexpr const char* kHazardsetEvalFullVar = "HAZARDSET_EVAL_FULL";

/// One ground-truth object in the full evaluation, in truth order.
struct ObjectEval {
  std::string label;
  std::string truth;               ///< "hazard" or "benign"
  bool reported = false;           ///< written `report=hazard` or `report=nothing`
  std::optional<double> penalty;   ///< missed hazard or false alarm
};

struct HazardsetEval {
  std::string vname;
  std::string report_name;
  double total_score = 0.0;
  double norm_score = 0.0;
  double score_missed_hazards = 0.0;
  double score_false_alarms = 0.0;
  double score_time_overage = 0.0;
  long total_objects = 0;
  double total_time_s = 0.0;      ///< search time at the report (0 if the search never started)
  double received_time_s = 0.0;   ///< report time since the grader started
  double start_time_s = 0.0;      ///< search start since the grader started (0: never started)
  long missed_hazards = 0;
  long correct_hazards = 0;
  long false_alarms = 0;
  double penalty_false_alarm = 0.0;
  double penalty_missed_hazard = 0.0;
  double penalty_max_time_over = 0.0;
  double penalty_max_time_rate = 0.0;
  double max_time_s = 0.0;
  std::vector<ObjectEval> object_report;  ///< the full form only
};

hazard::Parsed<HazardsetEval> parse_hazardset_eval(std::string_view text);
/// The short form (HAZARDSET_EVAL).
std::string format_hazardset_eval(const HazardsetEval& eval);
/// The full form (HAZARDSET_EVAL_FULL): the short form plus `,object_report={...}`.
std::string format_hazardset_eval_full(const HazardsetEval& eval);

}  // namespace mission
