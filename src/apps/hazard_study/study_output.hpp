#pragma once
// hazard_study's outputs: one JSON line per mission, and the summary per setting (mean,
// standard deviation, 95 % confidence interval of the score).

#include <string>
#include <vector>

#include "mission_run.hpp"

namespace hazard_study {

/// {"setting":...,["field_seed":G,]"seed":S,"end":...,"score":X,"found":F,"missed":M,
///  "false_alarms":A,"time_used":T,"detections":D,"classifications":C,"sim_s":S} and '\n';
///  field_seed only with a generated field. A value the mission
/// did not produce (no grade before max_time) is null. Numbers are the shortest text that reads
/// back as the same double.
std::string json_line(const MissionResult& result);

/// The two-sided 95 % quantile of Student's t with `df` >= 1 degrees of freedom.
double t_quantile_975(std::size_t df);

/// The scores of one setting, in mission order.
struct SettingScores {
  std::string setting;
  std::vector<double> scores;
  std::size_t missions = 0;
  std::size_t max_time = 0;  ///< missions that stopped at max_time
};

/// A table: setting, missions, scored, mean, sd, the 95 % interval of the mean, max_time stops.
std::string summary_table(const std::vector<SettingScores>& settings);

}  // namespace hazard_study
