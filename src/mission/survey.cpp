// Lawnmower planning and reacquisition routes. Contract: include/mission/survey.hpp.
//
// Algorithm (lawnmower): rotate into a frame whose first axis is the lane direction `a` and whose
// second is the across-track direction `c` (heading + 90). The region's extent across track is
// [c_min, c_max]; n = ceil(D / s) lanes are centred on it. Each lane's along-track extent is the
// along-track range of the region clipped to the band of half-width W around the lane, so slanted
// edges are covered to the lane's full sensor reach. Rejected alternative: clipping the lane line
// itself to the region, which leaves the corners of slanted edges (triangles, rhombi) uncovered.

#include "mission/survey.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/text.hpp"

namespace mission {

namespace {

struct LaneExtent {
  double across_m;
  double along_min_m;
  double along_max_m;
};

std::string check_options(const LawnmowerOptions& o) {
  auto bad = [](const char* name, double v, const char* rule) {
    return std::string("lawnmower option ") + name + "=" + base::fmt(v, 6) + " " + rule;
  };
  if (!std::isfinite(o.swath_half_width_m) || o.swath_half_width_m <= 0.0)
    return bad("swath_half_width_m", o.swath_half_width_m, "must be > 0");
  if (!std::isfinite(o.overlap) || o.overlap < 0.0 || o.overlap >= 1.0)
    return bad("overlap", o.overlap, "must be in [0, 1)");
  if (!std::isfinite(o.lane_heading_deg))
    return bad("lane_heading_deg", o.lane_heading_deg, "must be finite");
  if (!std::isfinite(o.lane_extension_m) || o.lane_extension_m < 0.0)
    return bad("lane_extension_m", o.lane_extension_m, "must be >= 0");
  return {};
}

std::vector<LaneExtent> lane_extents(const ConvexPolygon& region, glm::dvec2 along,
                                     glm::dvec2 across, double half_width_m, double spacing_m) {
  double c_min = std::numeric_limits<double>::infinity();
  double c_max = -c_min;
  for (const auto& v : region.vertices()) {
    c_min = std::min(c_min, glm::dot(across, v));
    c_max = std::max(c_max, glm::dot(across, v));
  }
  const double extent_m = c_max - c_min;
  const int lane_count = std::max(1, static_cast<int>(std::ceil(extent_m / spacing_m)));
  const double centre_m = 0.5 * (c_min + c_max);
  std::vector<LaneExtent> lanes;
  for (int k = 0; k < lane_count; ++k) {
    const double offset_m = centre_m + (k - 0.5 * (lane_count - 1)) * spacing_m;
    const auto band = clip_to_band(region.vertices(), across, offset_m - half_width_m,
                                   offset_m + half_width_m);
    if (band.empty()) continue;
    LaneExtent lane{offset_m, std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    for (const auto& p : band) {
      lane.along_min_m = std::min(lane.along_min_m, glm::dot(along, p));
      lane.along_max_m = std::max(lane.along_max_m, glm::dot(along, p));
    }
    lanes.push_back(lane);
  }
  return lanes;
}

}  // namespace

base::Result<LawnmowerPlan> plan_lawnmower(const ConvexPolygon& region,
                                           const LawnmowerOptions& options) {
  using R = base::Result<LawnmowerPlan>;
  if (std::string problem = check_options(options); !problem.empty()) return R::fail(problem);
  const glm::dvec2 along = heading_vector(options.lane_heading_deg);
  const glm::dvec2 across = heading_vector(options.lane_heading_deg + 90.0);
  LawnmowerPlan plan;
  plan.lane_spacing_m = 2.0 * options.swath_half_width_m * (1.0 - options.overlap);
  std::vector<LaneExtent> lanes =
      lane_extents(region, along, across, options.swath_half_width_m, plan.lane_spacing_m);

  // Start at the lane end nearest the start point: possibly the last lane, possibly backwards.
  bool forward_first = true;
  if (options.start_m) {
    const glm::dvec2 s = *options.start_m;
    auto end_point = [&](const LaneExtent& l, bool at_min) {
      return across * l.across_m + along * (at_min ? l.along_min_m : l.along_max_m);
    };
    const LaneExtent& first = lanes.front();
    const LaneExtent& last = lanes.back();
    const double d[4] = {glm::length(end_point(first, true) - s),
                         glm::length(end_point(first, false) - s),
                         glm::length(end_point(last, true) - s),
                         glm::length(end_point(last, false) - s)};
    const int best = static_cast<int>(std::min_element(d, d + 4) - d);
    if (best >= 2) std::reverse(lanes.begin(), lanes.end());
    forward_first = (best % 2) == 0;
  }

  // Turns: each lane's waypoints reach out to the outer end of its neighbour on the same side,
  // so the connector between two lanes is square to them (two 90-degree corners) instead of a
  // diagonal that needs a sharper turn than the vehicle can anticipate.
  const std::size_t n = lanes.size();
  for (std::size_t k = 0; k < n; ++k) {
    const LaneExtent& l = lanes[k];
    const bool forward = ((k % 2) == 0) == forward_first;
    const glm::dvec2 low = across * l.across_m + along * l.along_min_m;
    const glm::dvec2 high = across * l.across_m + along * l.along_max_m;
    plan.lanes.push_back(forward ? Lane{low, high} : Lane{high, low});
    // The side where this lane begins is shared with the previous lane's turn, the side where it
    // ends with the next lane's turn; each junction reaches to the outer of its two lanes.
    double wp_min = l.along_min_m;
    double wp_max = l.along_max_m;
    const std::size_t min_side_neighbour = forward ? k - 1 : k + 1;  // k - 1 wraps for k = 0
    const std::size_t max_side_neighbour = forward ? k + 1 : k - 1;
    if (min_side_neighbour < n) wp_min = std::min(wp_min, lanes[min_side_neighbour].along_min_m);
    if (max_side_neighbour < n) wp_max = std::max(wp_max, lanes[max_side_neighbour].along_max_m);
    wp_min -= options.lane_extension_m;
    wp_max += options.lane_extension_m;
    const glm::dvec2 wp_low = across * l.across_m + along * wp_min;
    const glm::dvec2 wp_high = across * l.across_m + along * wp_max;
    plan.waypoints_m.push_back(forward ? wp_low : wp_high);
    plan.waypoints_m.push_back(forward ? wp_high : wp_low);
  }
  return R::ok(std::move(plan));
}

std::vector<glm::dvec2> plan_reacquire_route(glm::dvec2 start_m,
                                             const std::vector<glm::dvec2>& objects_m,
                                             const ReacquireOptions& options) {
  std::vector<glm::dvec2> route;
  std::vector<bool> visited(objects_m.size(), false);
  glm::dvec2 here = start_m;
  glm::dvec2 last_direction{0.0, 1.0};  // north, used only when an object sits exactly here
  for (std::size_t n = 0; n < objects_m.size(); ++n) {
    std::size_t next = objects_m.size();
    double best_m = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < objects_m.size(); ++i) {
      const double d = glm::length(objects_m[i] - here);
      if (!visited[i] && d < best_m) {
        best_m = d;
        next = i;
      }
    }
    visited[next] = true;
    const glm::dvec2 object = objects_m[next];
    const glm::dvec2 direction = best_m > 0.0 ? (object - here) / best_m : last_direction;
    route.push_back(object - direction * options.leg_half_length_m);
    route.push_back(object + direction * options.leg_half_length_m);
    here = route.back();
    last_direction = direction;
  }
  return route;
}

}  // namespace mission
