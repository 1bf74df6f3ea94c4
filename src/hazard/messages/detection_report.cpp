#include "hazard/messages/detection_report.hpp"

#include "object_report.hpp"

namespace hazard {

Parsed<DetectionReport> parse_detection_report(std::string_view text) {
  detail::ObjectReportFields o;
  const std::string error = detail::read_object_report(detail::Fields(text), o);
  if (!error.empty()) return Parsed<DetectionReport>::fail(error);
  return Parsed<DetectionReport>::ok(DetectionReport{std::move(o.vname), o.x_m, o.y_m,
                                                     std::move(o.label), o.aspect_deg,
                                                     o.aspect_min_deg, o.aspect_max_deg});
}

std::string format_detection_report(const DetectionReport& r) {
  return detail::write_object_report({r.vname, r.x_m, r.y_m, r.label, r.aspect_deg,
                                      r.aspect_min_deg, r.aspect_max_deg},
                                     {});
}

std::string with_vname(std::string_view vname, std::string_view vehicle_report) {
  constexpr std::string_view kKey = "vname=";
  std::string out;
  out.reserve(kKey.size() + vname.size() + 1 + vehicle_report.size());
  out.append(kKey).append(vname).append(1, ',').append(vehicle_report);
  return out;
}

}  // namespace hazard
