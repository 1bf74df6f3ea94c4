#include "hazard/messages/view_circle.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "base/text_appender.hpp"

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

// Written through one TextAppender into a string reserved once: every detection and
// classification posts a circle (the same text as appending field by field).
std::string format_view_circle(const ViewCircle& c) {
  std::string out;
  out.reserve(200 + c.edge_color.size() + c.fill_color.size());
  {
    base::TextAppender text(out);
    text.put_field("x=", c.x_m, 2);
    text.put_field(",y=", c.y_m, 2);
    text.put_field(",radius=", c.radius_m, 5);
    text.put(",vertices=");
    char digits[16];
    const auto written = std::to_chars(digits, digits + sizeof digits, c.vertices);
    text.put(std::string_view(digits, static_cast<std::size_t>(written.ptr - digits)));
    if (c.duration_s) {
      text.put_field(",duration=", *c.duration_s, 1);
    }
    const auto field = [&text](std::string_view comma_key_equals, const std::string& value) {
      if (value.empty()) return;
      text.put(comma_key_equals);
      text.put(value);
    };
    field(",edge_color=", c.edge_color);
    field(",fill_color=", c.fill_color);
    text.put_field(",time=", c.time_s, 2);
    text.put_field(",vertex_size=", c.vertex_size, 1);
    text.put_field(",edge_size=", c.edge_size, 1);
    text.put_field(",fill_transparency=", std::clamp(c.fill_transparency, 0.0, 1.0), 2);
  }  // flushed here
  return out;
}

}  // namespace hazard
