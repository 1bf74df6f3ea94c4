#pragma once
// VIEW_CIRCLE (docs/messages.md; docs/differences.md D5, D19): detection and classification cues.
//
// Examples: detection      x=-52,y=-290,radius=10,vertices=12,duration=60,edge_color=white,
//                          fill_color=white,time=12.5,vertex_size=0,edge_size=1,
//                          fill_transparency=0.3
//           classification x=-52,y=-290,radius=10,vertices=5,edge_color=yellow,fill_color=yellow,
//                          time=40,vertex_size=0,edge_size=1,fill_transparency=0.3
// (each one line). x, y FMT(.,2); duration FMT(.,1) only when set; time FMT(.,2).

#include <optional>
#include <string>
#include <string_view>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ViewCircle {
  double x_m = 0.0;
  double y_m = 0.0;
  double radius_m = 0.0;
  int vertices = 0;
  std::optional<double> duration_s;  ///< absent: the viewer keeps the circle
  std::string edge_color;
  std::string fill_color;
  double time_s = 0.0;
  double vertex_size = 0.0;
  double edge_size = 0.0;
  double fill_transparency = 0.0;
};

Parsed<ViewCircle> parse_view_circle(std::string_view text);
std::string format_view_circle(const ViewCircle& circle);

}  // namespace hazard
