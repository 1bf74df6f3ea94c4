#pragma once
// Survey planning: lawnmower lanes over a convex region, and a reacquisition route through a
// list of object positions.
//
// Contract (lawnmower)
// - Lanes are straight lines along the lane heading (degrees, 0 = north = +y, clockwise,
//   as everywhere in this project), spaced `2 W (1 - overlap)` apart across track, where W is the
//   swath half width (docs/differences.md D2: W to each side).
// - Coverage guarantee: every point of the region lies within W of some lane segment (the lanes
//   without their extensions). Proof sketch: n = ceil(D / s) lanes (D = the region's extent across
//   track, s = spacing) are centred on the region, so the outer margins are at most s/2 <= W and
//   neighbouring lanes are s <= 2W apart; each lane runs over the whole along-track extent of the
//   region's slice within W of it (`clip_to_band`), so a point's nearest lane reaches past it.
// - Lanes alternate direction (boustrophedon) and are extended by `lane_extension_m` at both ends
//   so that the vehicle turns outside the region: the sensor blacks out while turning (manual 8),
//   and the extension lets the 2 s turn-rate window clear before the region starts. Each lane's
//   waypoints also reach as far out as its neighbours' ends, so the connector between lanes is
//   square to them: every turn is two 90-degree corners joined by a leg of one lane spacing. A
//   vehicle of minimum turn radius R turns cleanly when the spacing is at least 2R (Jake: 1.5 m/s
//   at 10 deg/s gives R = 8.6 m; spacings 45 m and 18 m).
// - The first lane is the one nearest `start_m` (when given), entered at its end nearest start.
//
// Contract (reacquisition route)
// - One straight leg per object, centred on it, `2 * leg_half_length_m` long, flown along the
//   direction of arrival so that the vehicle is straight (sensor on) when the object crosses the
//   swath. Objects are visited in greedy nearest-neighbour order from the start point (a tour,
//   not an optimal one; ties go to the earlier object in the input order).

#include <glm/vec2.hpp>

#include <cmath>
#include <optional>
#include <string>
#include "base/result.hpp"
#include <vector>

#include "base/text.hpp"
#include "mission/polygon.hpp"

namespace mission {

struct LawnmowerOptions {
  double swath_half_width_m = 25.0;  ///< W of the sensor setting (> 0); Jake's archie: 25
  /// Fraction of the swath shared by neighbouring lanes, [0, 1). Default 0.1 (5 m at W = 25):
  /// with no overlap, adjacent swaths only touch, and any cross-track error of the vehicle (heading
  /// noise, roll-out after a turn) opens a gap between them.
  double overlap = 0.1;
  double lane_heading_deg = 0.0;     ///< direction of the first lane; any value (normalised)
  double lane_extension_m = 20.0;    ///< lead-in/lead-out beyond the region at each lane end, >= 0
  std::optional<glm::dvec2> start_m; ///< where the vehicle starts; picks the first lane and end
};

struct Lane {
  glm::dvec2 begin_m;  ///< where the lane enters the region (before extension)
  glm::dvec2 end_m;    ///< where it leaves
};

struct LawnmowerPlan {
  double lane_spacing_m = 0.0;
  std::vector<Lane> lanes;             ///< in flying order, each in its flying direction
  std::vector<glm::dvec2> waypoints_m; ///< turn points in flying order (2 per lane, see contract)
};

/// Plans the lanes. Errors name the option and its value (W <= 0, overlap outside [0, 1),
/// negative extension, non-finite numbers).
base::Result<LawnmowerPlan> plan_lawnmower(const ConvexPolygon& region,
                                           const LawnmowerOptions& options);

struct ReacquireOptions {
  double leg_half_length_m = 30.0;  ///< straight flight before and after each object (> 0)
};

/// Waypoints visiting every object on a straight leg (see contract). Empty objects -> empty route.
std::vector<glm::dvec2> plan_reacquire_route(glm::dvec2 start_m,
                                             const std::vector<glm::dvec2>& objects_m,
                                             const ReacquireOptions& options);

// Inline: the vehicle calls each once per step.
namespace detail {
constexpr double kDegPerRad = 57.295779513082320876798;
}  // namespace detail

/// Unit vector of a heading (0 = +y, 90 = +x): (sin h, cos h).
inline glm::dvec2 heading_vector(double heading_deg) {
  const double h = heading_deg / detail::kDegPerRad;
  return {std::sin(h), std::cos(h)};
}
/// Heading of a direction vector, in [0, 360); (0,0) gives 0.
inline double heading_of(glm::dvec2 direction) {
  if (direction.x == 0.0 && direction.y == 0.0) return 0.0;
  return base::norm360(std::atan2(direction.x, direction.y) * detail::kDegPerRad);
}

}  // namespace mission
