#pragma once
// A NODE_REPORT's text for a vehicle at a pose, shared by the engine tests and hazard_replay's.
#include <string>
#include <utility>

#include "hazard/messages/node_report.hpp"

namespace hazard::testing {

inline std::string node_report(std::string name, double x, double y, double heading_deg = 0.0,
                               double speed_mps = 1.0) {
  NodeReport r;
  r.name = std::move(name);
  r.x_m = x;
  r.y_m = y;
  r.heading_deg = heading_deg;
  r.speed_mps = speed_mps;
  return format_node_report(r);
}

}  // namespace hazard::testing
