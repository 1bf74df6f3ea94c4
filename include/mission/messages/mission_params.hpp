#pragma once
// UHZ_MISSION_PARAMS (docs/mission-logic.md): the grader tells the vehicles how they will be
// scored.
//
// Example: penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=10,
//          penalty_max_time_over=0,max_time=0,penalty_max_time_rate=0,transit_path_width=20,
//          search_region=pts={-150,-75:-150,-400:400,-400:400,-75}
// (one line). Key order as above; numbers FMT(.,5) except max_time FMT(.,2);
// transit_path_width only when > 0 (the original's rule) and search_region only when the grader
// has a convex region.
//
// Parsing: keys case-insensitive, commas inside {...} do not split; a missing key keeps its
// default (uFldHazardMetric's, docs/mission-logic.md); a key whose value is not a number is an
// error naming the key and value; unknown keys are ignored (a later grader may add some).

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace mission {

inline constexpr const char* kMissionParamsVar = "UHZ_MISSION_PARAMS";

struct MissionParams {
  double penalty_missed_hazard = 100.0;
  double penalty_nonopt_hazard = 50.0;  ///< echoed only; never scored (docs/mission-logic.md)
  double penalty_false_alarm = 10.0;
  double penalty_max_time_over = 0.0;
  double max_time_s = 0.0;              ///< 0 = no limit
  double penalty_max_time_rate = 0.0;   ///< per second over max_time
  double transit_path_width_m = 20.0;   ///< half width of the transit lane; 0 = no lane
  std::optional<std::string> search_region;  ///< `pts={...}`
};

hazard::Parsed<MissionParams> parse_mission_params(std::string_view text);
std::string format_mission_params(const MissionParams& params);

}  // namespace mission
