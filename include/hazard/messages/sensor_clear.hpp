#pragma once
// UHZ_SENSOR_CLEAR (manual 3.2, differences.md D10): empty the vehicle's pending classification
// queue; the credits of the cleared entries are returned.
//
// Example: vname=archie

#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct SensorClear {
  std::string vname;
};

Parsed<SensorClear> parse_sensor_clear(std::string_view text);
std::string format_sensor_clear(const SensorClear& request);

}  // namespace hazard
