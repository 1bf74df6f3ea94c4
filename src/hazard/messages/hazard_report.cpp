#include "hazard/messages/hazard_report.hpp"

#include "object_report.hpp"

namespace hazard {

using Result = Parsed<HazardReport>;

Result parse_hazard_report(std::string_view text) {
  const detail::Fields f(text);
  detail::ObjectReportFields o;
  const std::string error = detail::read_object_report(f, o);
  if (!error.empty()) return Result::fail(error);
  const auto type = f.get("type");
  if (!type || type->empty()) return Result::fail(detail::missing_field("type"));
  ObjectType t;
  if (base::iequals(*type, "hazard")) {
    t = ObjectType::kHazard;
  } else if (base::iequals(*type, "benign")) {
    t = ObjectType::kBenign;
  } else {
    return Result::fail(detail::field_value("type", *type) + " is neither 'hazard' nor 'benign'");
  }
  return Result::ok(HazardReport{std::move(o.vname), o.x_m, o.y_m, std::move(o.label), t,
                                 o.aspect_deg, o.aspect_min_deg, o.aspect_max_deg});
}

std::string format_hazard_report(const HazardReport& r) {
  return detail::write_object_report(
      {r.vname, r.x_m, r.y_m, r.label, r.aspect_deg, r.aspect_min_deg, r.aspect_max_deg},
      type_name(r.type));
}

}  // namespace hazard
