#pragma once
// UHZ_SENSOR_REQUEST (docs/differences.md D12): the vehicle keeps its sensor on
// (600 s per request).
//
// Example: vname=archie

#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct SensorRequest {
  std::string vname;
};

Parsed<SensorRequest> parse_sensor_request(std::string_view text);
std::string format_sensor_request(const SensorRequest& request);

}  // namespace hazard
