#include <gtest/gtest.h>

#include <cmath>

#include "mission/geodesy.hpp"
#include "mission/survey.hpp"
#include "hazard/heading_history.hpp"
#include "base/text.hpp"
#include "mission/vehicle.hpp"

namespace mission {
namespace {

constexpr double kTick_s = 0.25;  // a 4 Hz application, as in the Jake mission
constexpr double kSensorMaxTurnRate_dps = 1.5;  // manual 8 default
constexpr double kSensorMaxSpeed_mps = 2.0;     // differences.md D14

// Runs the vehicle to completion (bounded), sampling at kTick_s.
std::vector<Pose> fly(SurveyVehicle& v, double start_s, double limit_s, double tick_s = kTick_s) {
  std::vector<Pose> poses;
  for (double t = start_s; t <= start_s + limit_s && !v.done(); t += tick_s)
    poses.push_back(v.advance_to(t));
  return poses;
}

TEST(Vehicle, ReachesEveryWaypointInOrderAndIsDone) {
  VehicleParams p;
  SurveyVehicle v(p, Pose{{0, 0}, 0, 0, 100.0});
  const std::vector<glm::dvec2> wps{{0, 100}, {100, 100}, {100, -50}, {-60, -50}, {-60, 200}};
  v.set_waypoints(wps);
  const auto poses = fly(v, 100.0, 2000.0, 0.05);
  ASSERT_TRUE(v.done());
  EXPECT_EQ(v.waypoints_reached(), wps.size());
  for (const auto& wp : wps) {
    double closest = 1e300;
    for (const Pose& pose : poses) closest = std::min(closest, glm::length(pose.position_m - wp));
    EXPECT_LE(closest, p.capture_radius_m) << wp.x << "," << wp.y;
  }
}

TEST(Vehicle, TurnRateNeverExceedsTheLimitBetweenAnyTwoPoses) {
  VehicleParams p;
  p.max_turn_rate_dps = 7.0;
  p.heading_noise_deg = 2.0;  // noise enters the command, so the limit must still hold
  SurveyVehicle v(p, Pose{{0, 0}, 180, 0, 0.0});
  v.set_waypoints({{0, 30}, {-40, 30}, {-40, -20}, {50, 60}});
  // Irregular application ticks, including ticks shorter and longer than the internal step.
  const double ticks[] = {0.013, 0.27, 0.05, 0.5, 0.111, 0.0501, 1.3};
  Pose last = v.advance_to(0.0);
  double t = 0.0;
  for (int i = 0; i < 20000 && !v.done(); ++i) {
    t += ticks[i % 7];
    const Pose now = v.advance_to(t);
    const double turn_deg = std::abs(base::norm180(now.heading_deg - last.heading_deg));
    const double rate = turn_deg / (t - last.time_s);
    ASSERT_LE(rate, p.max_turn_rate_dps * (1 + 1e-9)) << "at t=" << t;
    last = now;
  }
  EXPECT_TRUE(v.done());
}

TEST(Vehicle, TrackDoesNotDependOnTheApplicationTickRate) {
  VehicleParams p;
  p.heading_noise_deg = 1.0;
  const std::vector<glm::dvec2> wps{{0, 80}, {60, 80}, {60, 0}};
  SurveyVehicle fast(p, Pose{{0, 0}, 0, 0, 10.0});
  SurveyVehicle slow(p, Pose{{0, 0}, 0, 0, 10.0});
  fast.set_waypoints(wps);
  slow.set_waypoints(wps);
  for (double t = 10.0; t < 200.0; t += 0.1) fast.advance_to(t);
  for (double t = 10.0; t < 200.0; t += 0.7) slow.advance_to(t);
  const Pose a = fast.advance_to(200.0);
  const Pose b = slow.advance_to(200.0);
  EXPECT_NEAR(glm::length(a.position_m - b.position_m), 0.0, 1e-9);
  EXPECT_NEAR(a.heading_deg, b.heading_deg, 1e-9);
}

TEST(Vehicle, DoneVehicleStopsAndStaysPut) {
  SurveyVehicle v(VehicleParams{}, Pose{{0, 0}, 0, 0, 0.0});
  v.set_waypoints({{0, 30}});
  fly(v, 0.0, 100.0);
  ASSERT_TRUE(v.done());
  ASSERT_TRUE(v.done_time_s().has_value());
  EXPECT_NEAR(*v.done_time_s(), (30.0 - VehicleParams{}.capture_radius_m) / 1.5, 0.1);
  const Pose a = v.advance_to(500.0);
  const Pose b = v.advance_to(900.0);
  EXPECT_EQ(a.speed_mps, 0.0);
  EXPECT_EQ(a.position_m, b.position_m);
}

TEST(Vehicle, IdleUntilGivenARouteAndEmptyRouteIsDoneAtOnce) {
  SurveyVehicle v(VehicleParams{}, Pose{{5, 5}, 90, 0, 0.0});
  const Pose idle = v.advance_to(50.0);
  EXPECT_EQ(idle.position_m, glm::dvec2(5, 5));
  EXPECT_EQ(idle.speed_mps, 0.0);
  EXPECT_FALSE(v.done());
  v.set_waypoints({});
  EXPECT_TRUE(v.done());
  v.set_waypoints({{5, 50}});
  EXPECT_FALSE(v.done());
  const Pose moving = v.advance_to(60.0);
  EXPECT_EQ(moving.speed_mps, 1.5);
  EXPECT_GT(glm::length(moving.position_m - glm::dvec2(5, 5)), 5.0);
}

// set_waypoints keeps each leg's line for step(): the first one runs from where the vehicle is
// when the route arrives, not from where an earlier route started.
TEST(Vehicle, ANewRouteFliesAsAVehicleStartedWhereTheRouteArrived) {
  VehicleParams p;
  p.step_s = 0.0625;  // a binary fraction: both vehicles' grids meet exactly at t = 20
  SurveyVehicle rerouted(p, Pose{{0, 0}, 0, 0, 0.0});
  rerouted.set_waypoints({{0, 100}, {100, 100}});
  rerouted.advance_to(20.0);
  const SurveyVehicle::State at = rerouted.state();
  ASSERT_EQ(at.step_index, 320U);
  SurveyVehicle fresh(p, Pose{at.position_m, at.heading_deg, 0, 20.0});
  const std::vector<glm::dvec2> route{{-50, 60}, {-50, 120}, {20, 120}};
  rerouted.set_waypoints(route);
  fresh.set_waypoints(route);
  for (double t = 20.25; t <= 400.0 && !fresh.done(); t += 0.25) {
    const Pose a = rerouted.advance_to(t);
    const Pose b = fresh.advance_to(t);
    ASSERT_EQ(a.position_m, b.position_m) << "at t=" << t;
    ASSERT_EQ(a.heading_deg, b.heading_deg) << "at t=" << t;
  }
  EXPECT_TRUE(fresh.done());
  EXPECT_TRUE(rerouted.done());
}

TEST(Vehicle, InvalidParametersAreNamed) {
  VehicleParams p;
  p.speed_mps = 0;
  EXPECT_EQ(validate(p).error, "vehicle parameter speed_mps=0 must be > 0");
  p = {};
  p.heading_noise_tau_s = -1;
  EXPECT_EQ(validate(p).error, "vehicle parameter heading_noise_tau_s=-1 must be > 0");
  EXPECT_EQ(validate(VehicleParams{}).error, "");
}

// The survey as the sensor sees it: sampled at 4 Hz, the sensor is on while the 2 s turn
// rate is at most 1.5 deg/s, and an object is sensed when inside the swath rectangle (W across,
// 5 m along in total, differences.md D1). Every point of the region must be sensed with the sensor
// on.
void expect_flown_survey_covers_region(const VehicleParams& p, double heading_deg, double w_m) {
  const auto region =
      ConvexPolygon::parse("0,0:160,-20:200,120:20,140").value.value();
  LawnmowerOptions o;
  o.swath_half_width_m = w_m;
  o.lane_heading_deg = heading_deg;
  o.start_m = glm::dvec2{-30, -30};
  const auto plan = *plan_lawnmower(region, o).value;
  SurveyVehicle v(p, Pose{{-30, -30}, 45, 0, 0.0});
  v.set_waypoints(plan.waypoints_m);
  const auto poses = fly(v, 0.0, 20000.0);
  ASSERT_TRUE(v.done());
  hazard::HeadingHistory meter;
  std::vector<Pose> sensing;
  for (const Pose& pose : poses) {
    meter.add(pose.heading_deg, pose.time_s);
    if (meter.turn_rate_dps() <= kSensorMaxTurnRate_dps && pose.speed_mps <= kSensorMaxSpeed_mps)
      sensing.push_back(pose);
  }
  constexpr double kHalfLength_m = 2.5;
  const Bounds b = region.bounds();
  int uncovered = 0;
  for (double x = b.min_m.x; x <= b.max_m.x; x += 4.0) {
    for (double y = b.min_m.y; y <= b.max_m.y; y += 4.0) {
      if (!region.contains({x, y})) continue;
      bool seen = false;
      for (const Pose& pose : sensing) {
        const glm::dvec2 d = glm::dvec2{x, y} - pose.position_m;
        const glm::dvec2 ahead = heading_vector(pose.heading_deg);
        const glm::dvec2 right = heading_vector(pose.heading_deg + 90);
        if (std::abs(glm::dot(d, ahead)) <= kHalfLength_m && std::abs(glm::dot(d, right)) <= w_m) {
          seen = true;
          break;
        }
      }
      uncovered += seen ? 0 : 1;
    }
  }
  EXPECT_EQ(uncovered, 0) << "heading " << heading_deg << " W " << w_m;
}

TEST(Vehicle, FlownLawnmowerKeepsTheSensorOnOverTheWholeRegion_N4) {
  expect_flown_survey_covers_region(VehicleParams{}, 0.0, 25.0);
  expect_flown_survey_covers_region(VehicleParams{}, 63.0, 10.0);
}

TEST(Vehicle, LowPassHeadingNoiseStillKeepsTheSensorOn_N4) {
  VehicleParams p;
  p.heading_noise_deg = 1.0;  // with the default 20 s correlation time
  expect_flown_survey_covers_region(p, 0.0, 25.0);
}

TEST(Vehicle, HeadingNoiseHasTheStatedStationaryDeviation) {
  // 2000 independent seeds, each sampled after 10 correlation times: the disturbance's standard
  // deviation must match heading_noise_deg within 5 standard errors (se of a std ~ s/sqrt(2n)).
  VehicleParams p;
  p.heading_noise_deg = 3.0;
  p.heading_noise_tau_s = 2.0;
  constexpr int kSeeds = 2000;
  double sum2 = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    p.seed = static_cast<std::uint64_t>(seed);
    SurveyVehicle v(p, Pose{{0, 0}, 0, 0, 0.0});
    v.set_waypoints({{0, 10000}});
    v.advance_to(20.0);
    sum2 += v.state().noise_deg * v.state().noise_deg;
  }
  const double sd = std::sqrt(sum2 / kSeeds);
  EXPECT_NEAR(sd, 3.0, 5 * 3.0 / std::sqrt(2.0 * kSeeds));
}

TEST(Geodesy, RoundTripsToUnderOneMillimetreNearTheOrigin) {
  const LocalGeodesy geo(GeoPoint{43.825300, -70.330400});  // the MIT sailing pavilion datum
  double worst_m = 0.0;
  for (double x = -2000; x <= 2000; x += 250)
    for (double y = -2000; y <= 2000; y += 250) {
      const glm::dvec2 back = geo.to_local(geo.to_geo({x, y}));
      worst_m = std::max(worst_m, glm::length(back - glm::dvec2{x, y}));
    }
  EXPECT_LT(worst_m, 1e-3);
}

TEST(Geodesy, XIsEastAndYIsNorthWithTheEarthsScale) {
  const LocalGeodesy geo(GeoPoint{43.8253, -70.3304});
  const GeoPoint o = geo.to_geo({0, 0});
  EXPECT_NEAR(o.lat_deg, 43.8253, 1e-12);
  EXPECT_NEAR(o.lon_deg, -70.3304, 1e-12);
  const GeoPoint north = geo.to_geo({0, 1000});
  const GeoPoint east = geo.to_geo({1000, 0});
  // One degree of latitude is about 111.1 km at 44 N; one of longitude about 80.3 km.
  EXPECT_NEAR((north.lat_deg - o.lat_deg) * 111100.0, 1000.0, 5.0);
  EXPECT_NEAR((east.lon_deg - o.lon_deg) * 80300.0, 1000.0, 10.0);
  EXPECT_NEAR(north.lon_deg, o.lon_deg, 1e-9);
}

}  // namespace
}  // namespace mission
