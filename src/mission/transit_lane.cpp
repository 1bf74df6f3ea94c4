#include "mission/transit_lane.hpp"

namespace mission {

namespace {
int count_in_strip(const std::vector<glm::dvec2>& points, double x0, double x1, double y0,
                   double y1) {
  int n = 0;
  for (const auto& p : points) n += (p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1) ? 1 : 0;
  return n;
}
}  // namespace

std::optional<TransitLane> min_hazard_lane(const ConvexPolygon& region,
                                           const std::vector<glm::dvec2>& hazards_m,
                                           double half_width_m) {
  const Bounds b = region.bounds();
  const double begin_x = b.min_m.x + half_width_m;
  const double end_x = b.max_m.x - half_width_m;
  if (begin_x > end_x) return std::nullopt;
  std::optional<TransitLane> best;
  // Index-based so the candidates are exactly begin_x + k (no accumulated rounding); the bound
  // is the original's strict x < end_x, plus the single candidate when begin_x == end_x.
  for (long k = 0;; ++k) {
    const double x = begin_x + static_cast<double>(k) * kTransitLaneStep_m;
    if (!(x < end_x) && !(k == 0 && x == end_x)) break;
    const int n =
        count_in_strip(hazards_m, x - half_width_m, x + half_width_m, b.min_m.y, b.max_m.y);
    if (!best || n < best->hazard_count) best = TransitLane{x, n};
  }
  return best;
}

std::vector<glm::dvec2> transit_lane_corners(const ConvexPolygon& region, double x_m,
                                             double half_width_m) {
  const Bounds b = region.bounds();
  return {{x_m - half_width_m, b.min_m.y},
          {x_m - half_width_m, b.max_m.y},
          {x_m + half_width_m, b.max_m.y},
          {x_m + half_width_m, b.min_m.y}};
}

}  // namespace mission
