#include "hazard/spatial_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hazard {

namespace {

int clamp_cell(double offset_m, double cell_m, int cells) {
  const double c = std::floor(offset_m / cell_m);
  if (!(c >= 0)) return 0;  // also catches NaN
  if (c >= cells - 1) return cells - 1;
  return static_cast<int>(c);
}

/// Cells along an axis of half-extent `half_m`: at least 1, at most kMaxCellsPerAxis.
/// `cell_m` > 0 is at least the axis length / kMaxCellsPerAxis, so the ratio is finite.
int cells_along(double half_m, double cell_m) {
  const double cells = std::floor(half_m / cell_m * 2) + 1;
  return static_cast<int>(std::min<double>(cells, SpatialGrid::kMaxCellsPerAxis));
}

}  // namespace

SpatialGrid::SpatialGrid(const std::vector<glm::dvec2>& positions) {
  const std::size_t n = positions.size();
  if (n == 0) {
    cell_start_.assign(2, 0);
    return;
  }
  min_x_ = max_x_ = positions[0].x;
  min_y_ = max_y_ = positions[0].y;
  for (const auto& p : positions) {
    min_x_ = std::min(min_x_, p.x);
    max_x_ = std::max(max_x_, p.x);
    min_y_ = std::min(min_y_, p.y);
    max_y_ = std::max(max_y_, p.y);
  }
  // The field is measured in half-extents: two finite coordinates of opposite sign (x = 9e307
  // and -9e307) span more than the largest double, and an infinite extent would make the cell
  // size infinite and the cell counts NaN. The cell size and the counts stay finite.
  const double half_w = max_x_ / 2 - min_x_ / 2, half_h = max_y_ / 2 - min_y_ / 2;
  const double by_density = 2 * std::sqrt(half_w) * std::sqrt(half_h) *
                            std::sqrt(kTargetObjectsPerCell / static_cast<double>(n));
  const double by_axis_limit = std::max(half_w, half_h) / kMaxCellsPerAxis * 2;
  // The density rule can still overflow for such a field: the largest double is cell enough.
  cell_m_ = std::min(std::max(by_density, by_axis_limit), std::numeric_limits<double>::max());
  if (!(cell_m_ > 0)) cell_m_ = 1.0;  // every object at one point
  nx_ = cells_along(half_w, cell_m_);
  ny_ = cells_along(half_h, cell_m_);

  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  std::vector<std::uint32_t> cell_of(n);
  cell_start_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<std::uint32_t>(cell_y(positions[i].y)) *
                       static_cast<std::uint32_t>(nx_) +
                   static_cast<std::uint32_t>(cell_x(positions[i].x));
    cell_of[i] = c;
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  ids_.resize(n);
  positions_.resize(n);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t slot = fill[cell_of[i]]++;
    ids_[slot] = static_cast<std::uint32_t>(i);
    positions_[slot] = positions[i];
  }
}

int SpatialGrid::cell_x(double x) const { return clamp_cell(x - min_x_, cell_m_, nx_); }
int SpatialGrid::cell_y(double y) const { return clamp_cell(y - min_y_, cell_m_, ny_); }

}  // namespace hazard
