#include "mission/messages/mission_params.hpp"

#include "base/text.hpp"

namespace mission {

using Result = hazard::Parsed<MissionParams>;

Result parse_mission_params(std::string_view text) {
  MissionParams p;
  struct Slot {
    const char* key;
    double* value;
  };
  const Slot slots[] = {{"penalty_missed_hazard", &p.penalty_missed_hazard},
                        {"penalty_nonopt_hazard", &p.penalty_nonopt_hazard},
                        {"penalty_false_alarm", &p.penalty_false_alarm},
                        {"penalty_max_time_over", &p.penalty_max_time_over},
                        {"max_time", &p.max_time_s},
                        {"penalty_max_time_rate", &p.penalty_max_time_rate},
                        {"transit_path_width", &p.transit_path_width_m}};
  for (const base::KeyValue& kv : base::split_key_values(text, ',', /*respect_braces=*/true)) {
    const std::string key = base::to_lower(kv.key);
    if (key == "search_region") {
      p.search_region = std::string(kv.value);
      continue;
    }
    for (const Slot& slot : slots) {
      if (key != slot.key) continue;
      const auto number = base::parse_number(kv.value);
      if (!number) {
        return Result::fail("UHZ_MISSION_PARAMS field '" + key + "' value '" +
                            std::string(kv.value) + "' is not a number");
      }
      *slot.value = *number;
    }
  }
  return Result::ok(std::move(p));
}

std::string format_mission_params(const MissionParams& p) {
  std::string out;
  out += "penalty_missed_hazard=" + base::fmt(p.penalty_missed_hazard, 5);
  out += ",penalty_nonopt_hazard=" + base::fmt(p.penalty_nonopt_hazard, 5);
  out += ",penalty_false_alarm=" + base::fmt(p.penalty_false_alarm, 5);
  out += ",penalty_max_time_over=" + base::fmt(p.penalty_max_time_over, 5);
  out += ",max_time=" + base::fmt(p.max_time_s, 2);
  out += ",penalty_max_time_rate=" + base::fmt(p.penalty_max_time_rate, 5);
  if (p.transit_path_width_m > 0.0)
    out += ",transit_path_width=" + base::fmt(p.transit_path_width_m, 5);
  if (p.search_region) out += ",search_region=" + *p.search_region;
  return out;
}

}  // namespace mission
