#include "object_report.hpp"

namespace hazard::detail {

std::string read_object_report(const Fields& f, ObjectReportFields& out) {
  if (const auto vname = f.get("vname")) {
    if (vname->empty()) return missing_field("vname");
    out.vname = std::string(*vname);
  }
  std::string error;
  const auto x = f.number("x", error);
  const auto y = f.number("y", error);
  out.aspect_deg = f.number("aspect", error);
  out.aspect_min_deg = f.number("aspect_min", error);
  out.aspect_max_deg = f.number("aspect_max", error);
  if (!error.empty()) return error;
  if (!x) return missing_field("x");
  if (!y) return missing_field("y");
  const auto label = f.get("label");
  if (!label || label->empty()) return missing_field("label");
  out.x_m = *x;
  out.y_m = *y;
  out.label = std::string(*label);
  return {};
}

std::string write_object_report(const ObjectReportFields& r, std::string_view type) {
  std::string out;
  if (r.vname) append_field(out, "vname", *r.vname);
  append_field(out, "x", base::fmt(r.x_m, 2));
  append_field(out, "y", base::fmt(r.y_m, 2));
  append_field(out, "label", r.label);
  if (!type.empty()) append_field(out, "type", type);
  if (r.aspect_deg) append_field(out, "aspect", base::fmt(*r.aspect_deg));
  if (r.aspect_min_deg) append_field(out, "aspect_min", base::fmt(*r.aspect_min_deg));
  if (r.aspect_max_deg) append_field(out, "aspect_max", base::fmt(*r.aspect_max_deg));
  return out;
}

}  // namespace hazard::detail
