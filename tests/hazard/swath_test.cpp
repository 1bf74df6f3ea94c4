// Swath geometry and containment (differences.md D1, D2, "Containment", T1, N1, N13).
#include <gtest/gtest.h>

#include <random>

#include "hazard/messages/view_polygon.hpp"
#include "hazard/swath.hpp"
#include "base/text.hpp"

namespace hazard {
namespace {

std::string pts(const Swath& s) {
  ViewPolygon p;
  const auto c = s.corners();
  p.points.assign(c.begin(), c.end());
  const std::string spec = format_view_polygon(p);
  return spec.substr(0, spec.find("},") + 1);
}

TEST(Swath, CornersOfCaseT1) {
  EXPECT_EQ(pts(Swath({0, 0}, 0, 25, 5)), "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5}");
  EXPECT_EQ(pts(Swath({0, 0}, 90, 25, 5)), "pts={2.5,-25:-2.5,-25:-2.5,25:2.5,25}");
}

TEST(Swath, CornersAreExactAtRightAngles) {
  const auto c = Swath({0, 0}, 270, 25, 5).corners();
  EXPECT_EQ(c[0], glm::dvec2(-2.5, 25));  // front-starboard when heading west
  const auto d = Swath({0, 0}, 180, 10, 4).corners();
  EXPECT_EQ(d[0], glm::dvec2(-10, -2));
}

TEST(Swath, RotatedCornersFollowTheRectangle) {
  // (10,-20), heading 45, W 10, L 10 (half 5): front-starboard = centre + 10 starboard + 5 ahead.
  const auto c = Swath({10, -20}, 45, 10, 10).corners();
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(c[0].x, 10 + 10 * s + 5 * s, 1e-12);
  EXPECT_NEAR(c[0].y, -20 - 10 * s + 5 * s, 1e-12);
  EXPECT_EQ(pts(Swath({10, -20}, 45, 10, 10)), "pts={20.6,-23.5:13.5,-30.6:-0.6,-16.5:6.5,-9.4}");
}

TEST(Swath, ContainmentIsInclusiveOnAxisAlignedEdges_D1_D2) {
  const Swath s({0, 0}, 0, 25, 5);  // across |x| <= 25, along |y| <= 2.5
  EXPECT_TRUE(s.contains({25, 2.5}));   // a vertex is inside
  EXPECT_TRUE(s.contains({-25, 0}));
  EXPECT_TRUE(s.contains({0, -2.5}));
  EXPECT_FALSE(s.contains({25.000001, 0}));
  EXPECT_FALSE(s.contains({0, 2.500001}));
  EXPECT_FALSE(s.contains({0, 5}));  // the original's 2L would include this (D1)
}

// Rotated headings: points 1 micrometre inside or outside each edge (differences.md "Containment").
TEST(Swath, ContainmentAtRotatedHeadingsOneMicrometreFromEdges) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> heading(0.0, 360.0);
  constexpr double kMicrometre = 1e-6;
  for (int i = 0; i < 500; ++i) {
    const double h = heading(rng), w = 5 + i % 40, l = 2 + i % 9;
    const glm::dvec2 c{123.4, -567.8};
    const Swath s(c, h, w, l);
    const SinCos sc = sin_cos_deg(h);
    const glm::dvec2 fwd{sc.sin, sc.cos}, stb{sc.cos, -sc.sin};
    for (int side : {-1, 1}) {
      EXPECT_TRUE(s.contains(c + stb * (side * (w - kMicrometre)))) << h;
      EXPECT_FALSE(s.contains(c + stb * (side * (w + kMicrometre)))) << h;
      EXPECT_TRUE(s.contains(c + fwd * (side * (l / 2 - kMicrometre)))) << h;
      EXPECT_FALSE(s.contains(c + fwd * (side * (l / 2 + kMicrometre)))) << h;
    }
  }
}

TEST(Swath, BoundsContainEveryContainedPoint) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Swath s({1e5, -2e5}, i * 1.7, 30, 8);
    const Box b = s.bounds();
    for (int k = 0; k < 50; ++k) {
      const glm::dvec2 p{1e5 + 35 * u(rng), -2e5 + 35 * u(rng)};
      if (s.contains(p)) {
        EXPECT_TRUE(p.x >= b.min_x && p.x <= b.max_x && p.y >= b.min_y && p.y <= b.max_y);
      }
    }
  }
}

TEST(Swath, SinCosExactAtQuarterTurnsAndWraps) {
  EXPECT_EQ(sin_cos_deg(90).cos, 0.0);
  EXPECT_EQ(sin_cos_deg(-90).sin, -1.0);
  EXPECT_EQ(sin_cos_deg(450).sin, 1.0);
  EXPECT_NEAR(sin_cos_deg(30).sin, 0.5, 1e-15);
}

}  // namespace
}  // namespace hazard
