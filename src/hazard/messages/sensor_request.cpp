#include "hazard/messages/sensor_request.hpp"

#include "fields.hpp"

namespace hazard {

Parsed<SensorRequest> parse_sensor_request(std::string_view text) {
  const detail::Fields f(text);
  std::string error;
  auto vname = detail::vehicle_name(f, "vname", error);
  if (!vname) return Parsed<SensorRequest>::fail(error);
  return Parsed<SensorRequest>::ok(SensorRequest{std::move(*vname)});
}

std::string format_sensor_request(const SensorRequest& request) { return "vname=" + request.vname; }

}  // namespace hazard
