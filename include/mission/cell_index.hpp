#pragma once
// A uniform grid of ids by square cell, for the hazard manager's objects and its own track.
//
// Contract
// - `add(id, p)` files `id` under the cell of `p`; cell indices are floor(coordinate / cell) clamped
//   to 32 bits (positions within 2e10 m of the origin at 10 m cells keep their own cells; a farther
//   one, or NaN, shares the edge cell), so any double is accepted.
// - `for_each_in_box(lo, hi, f)` calls f(id) for every id in a cell that meets the box [lo, hi]
//   (a superset of the ids whose points lie in the box), in a fixed order: cell column (x) ascending,
//   then row (y) ascending, then ids in the order they were added. An empty box visits nothing.
// - Cost: a pose's query visits every cell of its box, which in a sparse field is mostly empty; a
//   bit per hashed cell (a one-hash Bloom filter) says "certainly empty" for those without a map
//   look-up. A box with more cells than the index has occupied cells (a huge or hostile box) scans
//   the occupied cells instead, so no query costs more than the index's size (plus a sort).
// Why not a dense array over the objects' bounding box: one detection report far away would make it
// huge; the hash map stays proportional to the occupied cells whatever the coordinates.

#include <glm/vec2.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mission {

class CellIndex {
 public:
  /// `cell_m` > 0 and finite.
  explicit CellIndex(double cell_m);

  void add(std::uint32_t id, glm::dvec2 position_m);
  std::size_t occupied_cells() const { return cells_.size(); }

  template <class F>
  void for_each_in_box(glm::dvec2 lo_m, glm::dvec2 hi_m, F&& f) const {
    if (cells_.empty()) return;
    const Range r = range_of(lo_m, hi_m);
    if (r.x1 < r.x0 || r.y1 < r.y0) return;
    if (r.cells() > static_cast<double>(cells_.size())) {
      for (std::uint32_t c : occupied_in(r))
        for (std::uint32_t id : cells_[c].ids) f(id);
      return;
    }
    for (std::int64_t cx = r.x0; cx <= r.x1; ++cx) {
      for (std::int64_t cy = r.y0; cy <= r.y1; ++cy) {
        if (!maybe_occupied(cx, cy)) continue;
        const auto it = by_key_.find(key(cx, cy));
        if (it == by_key_.end()) continue;
        for (std::uint32_t id : cells_[it->second].ids) f(id);
      }
    }
  }

 private:
  struct Cell {
    std::int64_t cx;
    std::int64_t cy;
    std::vector<std::uint32_t> ids;  ///< in the order added
  };
  struct Range {
    std::int64_t x0, x1, y0, y1;  ///< inclusive cell indices
    double cells() const {
      return static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1);
    }
  };
  static constexpr unsigned kFilterBitsLog2 = 14;  ///< 2 KiB of filter per index

  /// Cell indices are clamped to 32 bits: the conversion to an integer stays defined whatever
  /// the coordinate, and a key holds both indices.
  static constexpr double kMaxCellIndex = 2147483647.0;
  std::int64_t cell_of(double v) const {
    const double c = std::floor(v / cell_m_);
    if (!(c > -kMaxCellIndex)) return -static_cast<std::int64_t>(kMaxCellIndex);
    if (c > kMaxCellIndex) return static_cast<std::int64_t>(kMaxCellIndex);
    return static_cast<std::int64_t>(c);
  }
  Range range_of(glm::dvec2 lo_m, glm::dvec2 hi_m) const {
    return Range{cell_of(lo_m.x), cell_of(hi_m.x), cell_of(lo_m.y), cell_of(hi_m.y)};
  }
  /// Bits shifted as unsigned: shifting a negative index is undefined behaviour.
  static std::int64_t key(std::int64_t cx, std::int64_t cy) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(cx) << 32) ^
                                     (static_cast<std::uint64_t>(cy) & 0xffffffffULL));
  }
  /// Multiplicative hashing of both indices; the top bits are the best mixed.
  static std::uint64_t filter_bit(std::int64_t cx, std::int64_t cy) {
    const std::uint64_t h = static_cast<std::uint64_t>(cx) * 0x9E3779B97F4A7C15ULL ^
                            static_cast<std::uint64_t>(cy) * 0xC2B2AE3D27D4EB4FULL;
    return h >> (64 - kFilterBitsLog2);
  }
  bool maybe_occupied(std::int64_t cx, std::int64_t cy) const {
    const std::uint64_t bit = filter_bit(cx, cy);
    return (filter_[bit >> 6] >> (bit & 63u)) & 1u;
  }
  /// The occupied cells inside `r`, column then row ascending.
  std::vector<std::uint32_t> occupied_in(const Range& r) const;

  double cell_m_;
  std::vector<Cell> cells_;
  std::unordered_map<std::int64_t, std::uint32_t> by_key_;  ///< cell key -> index in cells_
  std::array<std::uint64_t, (1u << kFilterBitsLog2) / 64> filter_{};
};

}  // namespace mission
