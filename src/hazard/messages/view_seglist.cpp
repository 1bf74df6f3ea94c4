#include "hazard/messages/view_seglist.hpp"

#include "fields.hpp"

namespace hazard {

using Result = Parsed<ViewSeglist>;

Result parse_view_seglist(std::string_view text) {
  const detail::Fields f(text, /*respect_braces=*/true);
  ViewSeglist s;
  const auto pts = f.get("pts");
  if (!pts) return Result::fail(detail::missing_field("pts"));
  auto points = detail::parse_points(*pts);
  if (!points) return Result::fail(detail::field_value("pts", *pts) + " is not a point list");
  s.points = std::move(*points);
  s.edge_color = std::string(f.get("edge_color").value_or(""));
  std::string error;
  s.vertex_size = f.number("vertex_size", error).value_or(0.0);
  s.edge_size = f.number("edge_size", error).value_or(0.0);
  if (!error.empty()) return Result::fail(error);
  return Result::ok(std::move(s));
}

std::string format_view_seglist(const ViewSeglist& s) {
  std::string out = "pts=" + detail::format_points(s.points, 1);
  if (!s.edge_color.empty()) detail::append_field(out, "edge_color", s.edge_color);
  detail::append_field(out, "vertex_size", base::fmt(s.vertex_size, 1));
  detail::append_field(out, "edge_size", base::fmt(s.edge_size, 1));
  return out;
}

}  // namespace hazard
