#include "hazard/messages/view_marker.hpp"

#include <algorithm>

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ViewMarker>;

Result parse_view_marker(std::string_view text) {
  const detail::Fields f(text);
  ViewMarker m;
  std::string error;
  const auto x = f.number("x", error);
  const auto y = f.number("y", error);
  m.width_m = f.number("width", error).value_or(0.0);
  m.fill_transparency = f.number("fill_transparency", error);
  if (!error.empty()) return Result::fail(error);
  if (!x) return Result::fail(detail::missing_field("x"));
  if (!y) return Result::fail(detail::missing_field("y"));
  m.x_m = *x;
  m.y_m = *y;
  m.primary_color = std::string(f.get("primary_color").value_or(""));
  m.shape = std::string(f.get("type").value_or(""));
  m.label = std::string(f.get("label").value_or(""));
  return Result::ok(std::move(m));
}

std::string format_view_marker(const ViewMarker& m) {
  std::string out;
  detail::append_field(out, "x", base::fmt(m.x_m, 2));
  detail::append_field(out, "y", base::fmt(m.y_m, 2));
  detail::append_field(out, "width", base::fmt(m.width_m, 2));
  if (!m.primary_color.empty()) detail::append_field(out, "primary_color", m.primary_color);
  if (!m.shape.empty()) detail::append_field(out, "type", m.shape);
  if (!m.label.empty()) detail::append_field(out, "label", m.label);
  if (m.fill_transparency) {
    detail::append_field(out, "fill_transparency",
                         base::fmt(std::clamp(*m.fill_transparency, 0.0, 1.0), 2));
  }
  return out;
}

}  // namespace hazard
