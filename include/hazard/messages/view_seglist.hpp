#pragma once
// VIEW_SEGLIST (docs/messages.md, differences.md "Visuals"): the aspect axis of an object, drawn
// with the markers for every object that has an aspect (0 included).
//
// Example: pts={37,-192:37,-222},edge_color=gray70,vertex_size=0,edge_size=1
// Points FMT(.,1).

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "hazard/messages/parsed.hpp"

namespace hazard {

struct ViewSeglist {
  std::vector<glm::dvec2> points;
  std::string edge_color;
  double vertex_size = 0.0;
  double edge_size = 0.0;
};

Parsed<ViewSeglist> parse_view_seglist(std::string_view text);
std::string format_view_seglist(const ViewSeglist& seglist);

}  // namespace hazard
