#pragma once
// VIEW_MARKER (docs/messages.md, manual 7.6): one object of the field, drawn at start-up and on
// each PMV_CONNECT when show_hazards is true.
//
// Examples: x=-52,y=-290,width=8,primary_color=green,type=triangle,label=75
//           x=-41,y=-246,width=8,primary_color=light_blue,type=triangle,label=82,
//             fill_transparency=0.5
// x, y, width FMT(.,2); fill_transparency (benign objects: 1 - hr, 0.5 without hr) FMT(.,2).

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ViewMarker {
  double x_m = 0.0;
  double y_m = 0.0;
  double width_m = 0.0;
  std::string primary_color;
  std::string shape;  ///< written as `type=`
  std::string label;
  std::optional<double> fill_transparency;
};

Parsed<ViewMarker> parse_view_marker(std::string_view text);
std::string format_view_marker(const ViewMarker& marker);

}  // namespace hazard
