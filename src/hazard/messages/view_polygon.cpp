#include "hazard/messages/view_polygon.hpp"

#include <algorithm>

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ViewPolygon>;

Result parse_view_polygon(std::string_view text) {
  const detail::Fields f(text, /*respect_braces=*/true);
  ViewPolygon p;
  const auto pts = f.get("pts");
  if (!pts) return Result::fail(detail::missing_field("pts"));
  auto points = detail::parse_points(*pts);
  if (!points) return Result::fail(detail::field_value("pts", *pts) + " is not a point list");
  p.points = std::move(*points);
  p.label = std::string(f.get("label").value_or(""));
  p.msg = std::string(f.get("msg").value_or(""));
  p.edge_color = std::string(f.get("edge_color").value_or(""));
  p.fill_color = std::string(f.get("fill_color").value_or(""));
  std::string error;
  p.vertex_size = f.number("vertex_size", error).value_or(0.0);
  p.edge_size = f.number("edge_size", error).value_or(0.0);
  p.fill_transparency = f.number("fill_transparency", error).value_or(0.0);
  if (!error.empty()) return Result::fail(error);
  return Result::ok(std::move(p));
}

// Appended in place (one string, no temporaries): every vehicle's swath is posted each iteration.
std::string format_view_polygon(const ViewPolygon& p) {
  std::string out;
  out.reserve(160 + 24 * p.points.size() + p.label.size() + p.msg.size());
  out += "pts=";
  detail::append_points(out, p.points, 1);
  // ",key=" as one literal: `out` is not empty here (detail::append_field's one question).
  const auto field = [&out](const char* comma_key_equals, const std::string& value) {
    if (!value.empty()) out.append(comma_key_equals).append(value);
  };
  field(",label=", p.label);
  field(",msg=", p.msg);
  field(",edge_color=", p.edge_color);
  field(",fill_color=", p.fill_color);
  out += ",vertex_size=";
  base::append_fmt(out, p.vertex_size, 1);
  out += ",edge_size=";
  base::append_fmt(out, p.edge_size, 1);
  out += ",fill_transparency=";
  base::append_fmt(out, std::clamp(p.fill_transparency, 0.0, 1.0), 2);
  return out;
}

}  // namespace hazard
