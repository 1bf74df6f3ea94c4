#pragma once
// VIEW_POLYGON (docs/messages.md, manual 7.5): a vehicle's sensor swath for pMarineViewer.
//
// Example: pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90,
//          edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2
// (one line). Points FMT(.,1); fill white while the sensor is on, red while it is off (turning
// or too fast); fill_transparency FMT(.,2) clipped to [0, 1].

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ViewPolygon {
  std::vector<glm::dvec2> points;
  std::string label;
  std::string msg;
  std::string edge_color;
  std::string fill_color;
  double vertex_size = 0.0;
  double edge_size = 0.0;
  double fill_transparency = 0.0;
};

Parsed<ViewPolygon> parse_view_polygon(std::string_view text);
std::string format_view_polygon(const ViewPolygon& polygon);

}  // namespace hazard
