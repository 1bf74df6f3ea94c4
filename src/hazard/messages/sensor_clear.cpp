#include "hazard/messages/sensor_clear.hpp"

#include "hazard/messages/sensor_request.hpp"

namespace hazard {

// The same payload as UHZ_SENSOR_REQUEST (a vehicle name only), so the same parser.
Parsed<SensorClear> parse_sensor_clear(std::string_view text) {
  Parsed<SensorRequest> p = parse_sensor_request(text);
  if (!p) return Parsed<SensorClear>::fail(std::move(p.error));
  return Parsed<SensorClear>::ok(SensorClear{std::move(p.value->vname)});
}

std::string format_sensor_clear(const SensorClear& request) {
  return format_sensor_request({request.vname});
}

}  // namespace hazard
