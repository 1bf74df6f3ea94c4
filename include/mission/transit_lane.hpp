#pragma once
// The minimum-hazard transit lane (uFldHazardMetric's xpath; also uFldHazardMgr's
// `xpath=` part; docs/mission-logic.md): a vertical (north-south) strip of half width w through the
// search region that contains the fewest hazards.
//
// Rule: x runs from min_x + w while x < max_x - w in 1 m steps (min_x, max_x: the region's
// bounding box); the strip [x - w, x + w] x [min_y, max_y] counts the given points inside or on
// its boundary; the first x with the fewest points wins. When min_x + w > max_x - w there is no
// lane. When min_x + w == max_x - w exactly, the original loop never runs and reports x = min_x + w
// with a count of 0 without counting; we evaluate that single x (the count is then real).

#include <glm/vec2.hpp>

#include <optional>
#include <vector>

#include "mission/polygon.hpp"

namespace mission {

/// Step between candidate lane centres (m): the original's loop increment.
inline constexpr double kTransitLaneStep_m = 1.0;

struct TransitLane {
  double x_m = 0.0;        ///< lane centre
  int hazard_count = 0;    ///< points inside the lane
};

std::optional<TransitLane> min_hazard_lane(const ConvexPolygon& region,
                                           const std::vector<glm::dvec2>& hazards_m,
                                           double half_width_m);

/// The lane's rectangle over the region's y extent, corners in the original's order
/// (x-w,ymin), (x-w,ymax), (x+w,ymax), (x+w,ymin).
std::vector<glm::dvec2> transit_lane_corners(const ConvexPolygon& region, double x_m,
                                             double half_width_m);

}  // namespace mission
