#pragma once
// Uniform-grid spatial index over the field's object positions.
//
// Contract: for_each_in_box(box, f) calls f(id, position) exactly once for every point whose
// position lies inside the closed box, possibly also for some points just outside it (whole cells
// are visited), never for a point in a cell the box does not touch. Order is deterministic (cell
// by cell, row-major, then insertion order), so callers that need an order sort what they keep.
// Built once; positions never move (the field is static ground truth).
//
// Algorithm: cell size chosen so that the average occupied cell holds about
// kTargetObjectsPerCell objects, with at most kMaxCellsPerAxis cells per axis; storage is
// compressed rows (cell_start offsets into one array of ids and one of positions, sorted by
// cell), so a query reads contiguous memory and the whole index costs
// (8 + 16) bytes per object + 4 bytes per cell.
// Rejected alternatives: a k-d tree (no gain for near-uniform fields, harder to reason about),
// a hash of occupied cells (only better for extremely sparse fields).

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace hazard {

struct Box {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

/// The smallest box holding both `a` and `b`.
inline Box merged(const Box& a, const Box& b) {
  return Box{std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
             std::max(a.max_y, b.max_y)};
}

class SpatialGrid {
 public:
  /// Average objects per cell the sizing aims at.
  static constexpr double kTargetObjectsPerCell = 2.0;
  /// Upper bound on cells along one axis (keeps a long thin field's grid small).
  static constexpr int kMaxCellsPerAxis = 4096;

  SpatialGrid() = default;
  explicit SpatialGrid(const std::vector<glm::dvec2>& positions);

  template <class F>
  void for_each_in_box(const Box& box, F&& f) const {
    if (ids_.empty() || box.max_x < min_x_ || box.max_y < min_y_ || box.min_x > max_x_ ||
        box.min_y > max_y_) {
      return;
    }
    const int cx0 = cell_x(box.min_x), cx1 = cell_x(box.max_x);
    const int cy0 = cell_y(box.min_y), cy1 = cell_y(box.max_y);
    for (int cy = cy0; cy <= cy1; ++cy) {
      const std::size_t row = static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx_);
      const std::uint32_t begin = cell_start_[row + static_cast<std::size_t>(cx0)];
      const std::uint32_t end = cell_start_[row + static_cast<std::size_t>(cx1) + 1];
      for (std::uint32_t i = begin; i < end; ++i) f(ids_[i], positions_[i]);
    }
  }

  double cell_size_m() const { return cell_m_; }
  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }
  /// Bytes the index holds (capacity).
  std::size_t memory_bytes() const {
    return (cell_start_.capacity() + ids_.capacity()) * sizeof(std::uint32_t) +
           positions_.capacity() * sizeof(glm::dvec2);
  }

 private:
  int cell_x(double x) const;
  int cell_y(double y) const;

  double min_x_ = 0, min_y_ = 0, max_x_ = 0, max_y_ = 0;
  double cell_m_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_start_;  ///< nx*ny+1 offsets
  std::vector<std::uint32_t> ids_;         ///< object ids sorted by cell
  std::vector<glm::dvec2> positions_;      ///< positions in the same order as ids_
};

}  // namespace hazard
