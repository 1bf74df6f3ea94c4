#pragma once
// SURVEY_ROUTE_<V>: a new route for the simulated vehicle V (posted by pHazardMgr for a
// reacquisition, or by hand with moos-cli / uPokeDB).
//
// Example: SURVEY_ROUTE_BETTY = pts={-52,-260:-52,-320:-41,-276:-41,-216}
//
// The value is a point list in libmission's text form (mission::format_points writes it,
// mission::parse_points reads it: `pts={x1,y1:x2,y2:...}` or `x1,y1:x2,y2:...`), so the message
// has one parser and one formatter. The variable carries the vehicle name, upper-cased like the
// sensor's per-vehicle variables, because on a single MOOSDB every vehicle's simulator would
// otherwise follow every route (differences.md "Who hears what").

#include <string>
#include <string_view>

#include "base/text.hpp"

namespace usim_survey_vehicle {

inline constexpr const char* kSurveyRouteVar = "SURVEY_ROUTE";

/// "SURVEY_ROUTE_" + upper-cased vehicle name.
inline std::string survey_route_variable_for(std::string_view vname) {
  return std::string(kSurveyRouteVar) + "_" + base::to_upper(vname);
}

}  // namespace usim_survey_vehicle
