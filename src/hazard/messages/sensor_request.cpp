#include "hazard/messages/sensor_request.hpp"

#include "fields.hpp"

namespace hazard {

Parsed<SensorRequest> parse_sensor_request(std::string_view text) {
  const detail::Fields f(text);
  const auto vname = f.get("vname");
  if (!vname || vname->empty()) return Parsed<SensorRequest>::fail(detail::missing_field("vname"));
  return Parsed<SensorRequest>::ok(SensorRequest{std::string(*vname)});
}

std::string format_sensor_request(const SensorRequest& request) { return "vname=" + request.vname; }

}  // namespace hazard
