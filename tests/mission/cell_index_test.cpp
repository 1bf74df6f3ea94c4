#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

#include "mission/cell_index.hpp"

namespace mission {
namespace {

constexpr double kCell = 10.0;

// The contract's cell rule, written out independently of the index.
std::int64_t reference_cell(double v) {
  const double c = std::floor(v / kCell);
  if (!(c > -2147483647.0)) return -2147483647;
  if (c > 2147483647.0) return 2147483647;
  return static_cast<std::int64_t>(c);
}

struct Point {
  std::uint32_t id;
  glm::dvec2 p;
};

// Brute force: every id whose cell lies in the box's cell range, column, row, then id order.
std::vector<std::uint32_t> brute_force(const std::vector<Point>& points, glm::dvec2 lo,
                                       glm::dvec2 hi) {
  std::vector<std::tuple<std::int64_t, std::int64_t, std::uint32_t>> hits;
  for (const Point& q : points) {
    const std::int64_t cx = reference_cell(q.p.x), cy = reference_cell(q.p.y);
    if (cx >= reference_cell(lo.x) && cx <= reference_cell(hi.x) && cy >= reference_cell(lo.y) &&
        cy <= reference_cell(hi.y)) {
      hits.emplace_back(cx, cy, q.id);
    }
  }
  std::sort(hits.begin(), hits.end());
  std::vector<std::uint32_t> out;
  for (const auto& h : hits) out.push_back(std::get<2>(h));
  return out;
}

std::vector<std::uint32_t> visited(const CellIndex& index, glm::dvec2 lo, glm::dvec2 hi) {
  std::vector<std::uint32_t> out;
  index.for_each_in_box(lo, hi, [&](std::uint32_t id) { out.push_back(id); });
  return out;
}

// A coordinate from a mix of scales: near the origin, negative, large, huge, and non-finite.
double random_coordinate(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (std::uniform_int_distribution<int>(0, 9)(rng)) {
    case 0: return unit(rng) * 1e12;  // beyond the clamped cells
    case 1: return unit(rng) * 1e308;
    case 2: return std::numeric_limits<double>::quiet_NaN();
    case 3: return unit(rng) > 0 ? std::numeric_limits<double>::infinity()
                                 : -std::numeric_limits<double>::infinity();
    case 4: return std::floor(unit(rng) * 30.0) * kCell;  // exactly on a cell edge
    default: return unit(rng) * 300.0;
  }
}

TEST(CellIndex, VisitsTheSameIdsInTheSameOrderAsABruteForceScan) {
  std::mt19937_64 rng(20261128);
  for (int round = 0; round < 40; ++round) {
    CellIndex index(kCell);
    std::vector<Point> points;
    const int n = std::uniform_int_distribution<int>(0, 400)(rng);
    for (int i = 0; i < n; ++i) {
      // Clustered ids share cells, so a cell holds several ids in insertion order.
      const glm::dvec2 p{random_coordinate(rng), random_coordinate(rng)};
      points.push_back({static_cast<std::uint32_t>(i), p});
      index.add(static_cast<std::uint32_t>(i), p);
    }
    for (int q = 0; q < 200; ++q) {
      // Small boxes take the cell-by-cell path, large ones the scan of occupied cells.
      const glm::dvec2 c{random_coordinate(rng), random_coordinate(rng)};
      const double half = std::uniform_real_distribution<double>(0.0, q % 2 ? 40.0 : 3e3)(rng);
      const glm::dvec2 lo = c - glm::dvec2{half, half}, hi = c + glm::dvec2{half, half};
      ASSERT_EQ(visited(index, lo, hi), brute_force(points, lo, hi))
          << "round " << round << " box (" << lo.x << "," << lo.y << ")-(" << hi.x << "," << hi.y
          << ")";
    }
  }
}

TEST(CellIndex, EveryPointInsideTheBoxIsVisited) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  CellIndex index(kCell);
  std::vector<Point> points;
  for (std::uint32_t i = 0; i < 300; ++i) {
    points.push_back({i, {coord(rng), coord(rng)}});
    index.add(i, points.back().p);
  }
  for (int q = 0; q < 500; ++q) {
    const glm::dvec2 lo{coord(rng), coord(rng)};
    const glm::dvec2 hi = lo + glm::dvec2{std::fabs(coord(rng)) / 10.0, std::fabs(coord(rng))};
    const std::vector<std::uint32_t> got = visited(index, lo, hi);
    for (const Point& p : points) {
      if (p.p.x < lo.x || p.p.x > hi.x || p.p.y < lo.y || p.p.y > hi.y) continue;
      EXPECT_NE(std::find(got.begin(), got.end(), p.id), got.end()) << p.id;
    }
  }
}

TEST(CellIndex, EmptyIndexOrInvertedBoxVisitsNothing) {
  CellIndex index(kCell);
  EXPECT_TRUE(visited(index, {-1e9, -1e9}, {1e9, 1e9}).empty());
  index.add(3, {5.0, 5.0});
  EXPECT_EQ(visited(index, {0.0, 0.0}, {1.0, 1.0}), std::vector<std::uint32_t>{3});
  EXPECT_TRUE(visited(index, {20.0, 0.0}, {0.0, 20.0}).empty());  // min x beyond max x
  EXPECT_EQ(index.occupied_cells(), 1u);
}

// A hostile box (the whole plane) costs the occupied cells, not 2^64 cell look-ups.
TEST(CellIndex, AHugeBoxScansTheOccupiedCellsInOrder) {
  CellIndex index(kCell);
  index.add(0, {1e15, -1e15});
  index.add(1, {-5.0, 25.0});
  index.add(2, {-5.0, -25.0});
  index.add(3, {-1.0, 21.0});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(visited(index, {-inf, -inf}, {inf, inf}), (std::vector<std::uint32_t>{2, 1, 3, 0}));
}

}  // namespace
}  // namespace mission
