// Grid of ids by cell. Contract: include/mission/cell_index.hpp.
#include "mission/cell_index.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace mission {

CellIndex::CellIndex(double cell_m) : cell_m_(cell_m) {
  assert(std::isfinite(cell_m) && cell_m > 0.0);
}

void CellIndex::add(std::uint32_t id, glm::dvec2 position_m) {
  const std::int64_t cx = cell_of(position_m.x), cy = cell_of(position_m.y);
  const std::int64_t k = key(cx, cy);
  auto it = by_key_.find(k);  // find first: emplace would allocate a node every time
  if (it == by_key_.end()) {
    it = by_key_.emplace(k, static_cast<std::uint32_t>(cells_.size())).first;
    cells_.push_back(Cell{cx, cy, {}});
    const std::uint64_t bit = filter_bit(cx, cy);
    filter_[bit >> 6] |= std::uint64_t{1} << (bit & 63u);
  }
  cells_[it->second].ids.push_back(id);
}

std::vector<std::uint32_t> CellIndex::occupied_in(const Range& r) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < cells_.size(); ++i) {
    const Cell& c = cells_[i];
    if (c.cx >= r.x0 && c.cx <= r.x1 && c.cy >= r.y0 && c.cy <= r.y1) out.push_back(i);
  }
  std::sort(out.begin(), out.end(), [&](std::uint32_t a, std::uint32_t b) {
    return cells_[a].cx != cells_[b].cx ? cells_[a].cx < cells_[b].cx : cells_[a].cy < cells_[b].cy;
  });
  return out;
}

}  // namespace mission
