#include "object_report.hpp"

#include "base/text_appender.hpp"

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

// Written through one TextAppender into a string reserved once: every detection posts two
// reports and every classification two more (the same text as appending field by field).
std::string write_object_report(const ObjectReportFields& r, std::string_view type) {
  std::string out;
  out.reserve(96 + (r.vname ? r.vname->size() : 0) + r.label.size() + type.size());
  {
    base::TextAppender text(out);
    if (r.vname) {
      text.put("vname=");
      text.put(*r.vname);
      text.put(',');
    }
    text.put_field("x=", r.x_m, 2);
    text.put_field(",y=", r.y_m, 2);
    text.put(",label=");
    text.put(r.label);
    if (!type.empty()) {
      text.put(",type=");
      text.put(type);
    }
    const auto angle = [&text](std::string_view comma_key_equals, const std::optional<double>& value) {
      if (!value) return;
      text.put_field(comma_key_equals, *value, 5);
    };
    angle(",aspect=", r.aspect_deg);
    angle(",aspect_min=", r.aspect_min_deg);
    angle(",aspect_max=", r.aspect_max_deg);
  }  // flushed here
  return out;
}

}  // namespace hazard::detail
