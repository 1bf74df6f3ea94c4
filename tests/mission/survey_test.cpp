#include <gtest/gtest.h>

#include <cmath>

#include "mission/survey.hpp"

namespace mission {
namespace {

ConvexPolygon region_of(std::string_view text) {
  return ConvexPolygon::parse(text).value.value();
}

LawnmowerPlan must_plan(const ConvexPolygon& region, const LawnmowerOptions& options) {
  base::Result<LawnmowerPlan> plan = plan_lawnmower(region, options);
  if (!plan) ADD_FAILURE() << plan.error;
  return plan.value.value_or(LawnmowerPlan{});
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + ab * t));
}

// Worst distance from a grid of region points to the nearest lane (without extensions).
double worst_uncovered_distance(const ConvexPolygon& region, const LawnmowerPlan& plan,
                                double grid_m) {
  const Bounds b = region.bounds();
  double worst = 0.0;
  for (double x = b.min_m.x; x <= b.max_m.x; x += grid_m) {
    for (double y = b.min_m.y; y <= b.max_m.y; y += grid_m) {
      if (!region.contains({x, y})) continue;
      double nearest = 1e300;
      for (const Lane& lane : plan.lanes)
        nearest = std::min(nearest, distance_to_segment({x, y}, lane.begin_m, lane.end_m));
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

TEST(Lawnmower, LanesCoverEveryPointOfTheRegionWithinW) {
  const char* regions[] = {
      "-150,-75:-150,-400:400,-400:400,-75",  // Jake's region (manual 2.3)
      "0,0:300,0:150,260",                    // triangle: slanted edges
      "0,0:200,100:300,300:100,200",          // rhombus
      "0,-100:87,-50:87,50:0,100:-87,50:-87,-50",  // hexagon
  };
  for (const char* text : regions) {
    const ConvexPolygon region = region_of(text);
    for (double heading : {0.0, 37.0, 90.0, 135.0, 271.5}) {
      for (double overlap : {0.0, 0.25}) {
        for (double w : {25.0, 10.0}) {
          LawnmowerOptions o;
          o.swath_half_width_m = w;
          o.overlap = overlap;
          o.lane_heading_deg = heading;
          const LawnmowerPlan plan = must_plan(region, o);
          EXPECT_LE(worst_uncovered_distance(region, plan, 3.0), w + 1e-9)
              << text << " heading " << heading << " overlap " << overlap << " W " << w;
        }
      }
    }
  }
}

TEST(Lawnmower, SpacingIsTwoWTimesOneMinusOverlapAndLanesFollowTheHeading) {
  const ConvexPolygon region = region_of("0,0:400,0:400,300:0,300");
  LawnmowerOptions o;
  o.swath_half_width_m = 25;
  o.overlap = 0.2;
  o.lane_heading_deg = 90;  // east-west lanes
  const LawnmowerPlan plan = must_plan(region, o);
  EXPECT_DOUBLE_EQ(plan.lane_spacing_m, 40.0);
  ASSERT_EQ(plan.lanes.size(), 8u);  // ceil(300 / 40)
  for (std::size_t k = 0; k < plan.lanes.size(); ++k) {
    const Lane& lane = plan.lanes[k];
    EXPECT_NEAR(lane.begin_m.y, lane.end_m.y, 1e-9);  // east-west
    if (k > 0) {
      EXPECT_NEAR(std::abs(lane.begin_m.y - plan.lanes[k - 1].begin_m.y), 40.0, 1e-9);
    }
    // Boustrophedon: even lanes fly east (heading 90), odd lanes west.
    EXPECT_NEAR(heading_of(lane.end_m - lane.begin_m), k % 2 == 0 ? 90.0 : 270.0, 1e-9);
  }
  // The pattern is centred: equal margins at the bottom and top.
  const double bottom = std::min(plan.lanes.front().begin_m.y, plan.lanes.back().begin_m.y);
  const double top = std::max(plan.lanes.front().begin_m.y, plan.lanes.back().begin_m.y);
  EXPECT_NEAR(bottom - 0.0, 300.0 - top, 1e-9);
}

TEST(Lawnmower, WaypointsExtendEachLaneOutsideTheRegionWithSquareTurns) {
  // A triangle: every lane has a different extent, yet each connector is square to the lanes.
  const ConvexPolygon region = region_of("0,0:300,0:150,260");
  LawnmowerOptions o;
  o.swath_half_width_m = 25;
  o.lane_extension_m = 15;
  const LawnmowerPlan plan = must_plan(region, o);
  ASSERT_EQ(plan.waypoints_m.size(), 2 * plan.lanes.size());
  for (std::size_t k = 0; k < plan.lanes.size(); ++k) {
    const glm::dvec2 dir = glm::normalize(plan.lanes[k].end_m - plan.lanes[k].begin_m);
    const glm::dvec2 a = plan.waypoints_m[2 * k];
    const glm::dvec2 b = plan.waypoints_m[2 * k + 1];
    // On the lane's line, at least lane_extension_m beyond each end of the lane.
    EXPECT_NEAR(glm::dot(a - plan.lanes[k].begin_m, dir), -glm::length(a - plan.lanes[k].begin_m),
                1e-9);
    EXPECT_GE(glm::dot(plan.lanes[k].begin_m - a, dir), 15.0 - 1e-9);
    EXPECT_GE(glm::dot(b - plan.lanes[k].end_m, dir), 15.0 - 1e-9);
    if (k + 1 < plan.lanes.size()) {
      const glm::dvec2 connector = plan.waypoints_m[2 * k + 2] - b;
      EXPECT_NEAR(glm::dot(connector, dir), 0.0, 1e-9);
      EXPECT_NEAR(glm::length(connector), plan.lane_spacing_m, 1e-9);
    }
  }
}

TEST(Lawnmower, StartsAtTheLaneEndNearestTheStartPoint) {
  const ConvexPolygon region = region_of("0,0:200,0:200,200:0,200");
  LawnmowerOptions o;
  o.swath_half_width_m = 25;
  for (glm::dvec2 start : {glm::dvec2{-50, -50}, glm::dvec2{250, -50}, glm::dvec2{250, 260},
                           glm::dvec2{-10, 260}}) {
    o.start_m = start;
    const LawnmowerPlan plan = must_plan(region, o);
    double nearest = 1e300;
    for (const Lane& lane : plan.lanes)
      nearest = std::min(
          {nearest, glm::length(lane.begin_m - start), glm::length(lane.end_m - start)});
    EXPECT_NEAR(glm::length(plan.lanes.front().begin_m - start), nearest, 1e-9);
  }
}

TEST(Lawnmower, NarrowRegionGetsOneLane) {
  const ConvexPolygon region = region_of("0,0:10,0:10,300:0,300");
  LawnmowerOptions o;
  o.swath_half_width_m = 25;
  const LawnmowerPlan plan = must_plan(region, o);
  EXPECT_EQ(plan.lanes.size(), 1u);
}

TEST(Lawnmower, BadOptionsAreRejectedNamingTheOption) {
  const ConvexPolygon region = region_of("0,0:10,0:10,10");
  LawnmowerOptions o;
  o.swath_half_width_m = 0;
  EXPECT_EQ(plan_lawnmower(region, o).error,
            "lawnmower option swath_half_width_m=0 must be > 0");
  o = {};
  o.overlap = 1.0;
  EXPECT_EQ(plan_lawnmower(region, o).error,
            "lawnmower option overlap=1 must be in [0, 1)");
  o = {};
  o.lane_extension_m = -1;
  EXPECT_NE(plan_lawnmower(region, o).error.find("lane_extension_m=-1"),
            std::string::npos);
}

TEST(ReacquireRoute, EachObjectSitsInTheMiddleOfAStraightLeg) {
  const std::vector<glm::dvec2> objects{{100, 0}, {0, 50}, {105, 40}};
  const auto route = plan_reacquire_route({0, 0}, objects, ReacquireOptions{20});
  ASSERT_EQ(route.size(), 6u);
  // Nearest first: (0,50) is 50 away, (100,0) is 100 away.
  EXPECT_NEAR(glm::length((route[0] + route[1]) * 0.5 - glm::dvec2{0, 50}), 0, 1e-9);
  for (std::size_t i = 0; i < route.size(); i += 2) {
    EXPECT_NEAR(glm::length(route[i + 1] - route[i]), 40.0, 1e-9);
    if (i > 0) {  // each leg continues the line from the previous leg's end
      const glm::dvec2 approach = glm::normalize(route[i] - route[i - 1]);
      const glm::dvec2 leg = glm::normalize(route[i + 1] - route[i]);
      EXPECT_NEAR(glm::dot(approach, leg), 1.0, 1e-9);
    }
  }
  EXPECT_TRUE(plan_reacquire_route({0, 0}, {}, ReacquireOptions{}).empty());
}

TEST(Angles, HeadingsFollowSpecSection0) {
  EXPECT_NEAR(heading_of({1, 0}), 90, 1e-12);
  EXPECT_NEAR(heading_of({0, -1}), 180, 1e-12);
  EXPECT_NEAR(heading_of({-1, 1}), 315, 1e-12);
  EXPECT_EQ(heading_of({0, 0}), 0.0);
  EXPECT_NEAR(heading_vector(90).x, 1, 1e-15);
  EXPECT_NEAR(heading_vector(180).y, -1, 1e-15);
}

}  // namespace
}  // namespace mission
