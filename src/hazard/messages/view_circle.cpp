#include "hazard/messages/view_circle.hpp"

#include <algorithm>
#include <cmath>

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ViewCircle>;

Result parse_view_circle(std::string_view text) {
  const detail::Fields f(text);
  ViewCircle c;
  std::string error;
  const auto x = f.number("x", error);
  const auto y = f.number("y", error);
  const auto radius = f.number("radius", error);
  const auto vertices = f.number("vertices", error);
  c.duration_s = f.number("duration", error);
  c.time_s = f.number("time", error).value_or(0.0);
  c.vertex_size = f.number("vertex_size", error).value_or(0.0);
  c.edge_size = f.number("edge_size", error).value_or(0.0);
  c.fill_transparency = f.number("fill_transparency", error).value_or(0.0);
  if (!error.empty()) return Result::fail(error);
  if (!x) return Result::fail(detail::missing_field("x"));
  if (!y) return Result::fail(detail::missing_field("y"));
  if (!radius) return Result::fail(detail::missing_field("radius"));
  c.x_m = *x;
  c.y_m = *y;
  c.radius_m = *radius;
  c.vertices = vertices ? static_cast<int>(std::lround(*vertices)) : 0;
  c.edge_color = std::string(f.get("edge_color").value_or(""));
  c.fill_color = std::string(f.get("fill_color").value_or(""));
  return Result::ok(std::move(c));
}

std::string format_view_circle(const ViewCircle& c) {
  std::string out;
  detail::append_field(out, "x", base::fmt(c.x_m, 2));
  detail::append_field(out, "y", base::fmt(c.y_m, 2));
  detail::append_field(out, "radius", base::fmt(c.radius_m));
  detail::append_field(out, "vertices", std::to_string(c.vertices));
  if (c.duration_s) detail::append_field(out, "duration", base::fmt(*c.duration_s, 1));
  if (!c.edge_color.empty()) detail::append_field(out, "edge_color", c.edge_color);
  if (!c.fill_color.empty()) detail::append_field(out, "fill_color", c.fill_color);
  detail::append_field(out, "time", base::fmt(c.time_s, 2));
  detail::append_field(out, "vertex_size", base::fmt(c.vertex_size, 1));
  detail::append_field(out, "edge_size", base::fmt(c.edge_size, 1));
  detail::append_field(out, "fill_transparency", base::fmt(std::clamp(c.fill_transparency, 0.0, 1.0), 2));
  return out;
}

}  // namespace hazard
