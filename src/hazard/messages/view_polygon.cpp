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

// Written through one TextAppender into a string reserved once: every vehicle's swath is
// posted each iteration.
std::string format_view_polygon(const ViewPolygon& p) {
  std::string out;
  out.reserve(160 + 24 * p.points.size() + p.label.size() + p.msg.size());
  {
    base::TextAppender text(out);
    text.put("pts=");
    detail::append_points(text, p.points, 1);
    // ",key=" as one piece: the text is not empty here (detail::append_field's one question).
    const auto field = [&text](std::string_view comma_key_equals, const std::string& value) {
      if (value.empty()) return;
      text.put(comma_key_equals);
      text.put(value);
    };
    field(",label=", p.label);
    field(",msg=", p.msg);
    field(",edge_color=", p.edge_color);
    field(",fill_color=", p.fill_color);
    text.put_field(",vertex_size=", p.vertex_size, 1);
    text.put_field(",edge_size=", p.edge_size, 1);
    text.put_field(",fill_transparency=", std::clamp(p.fill_transparency, 0.0, 1.0), 2);
  }  // flushed here
  return out;
}

}  // namespace hazard
