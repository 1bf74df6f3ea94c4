#include <gtest/gtest.h>

#include <cmath>

#include "mission/outputs.hpp"
#include "mission/random.hpp"
#include "mission/vehicle_config.hpp"

namespace mission {
namespace {

TEST(VehicleConfig, TableAppliesAndNamesEveryProblem) {
  SurveyVehicleConfig c;
  EXPECT_EQ(apply_survey_vehicle_param(c, "SPEED", "1.2").error, "");
  EXPECT_EQ(c.vehicle.speed_mps, 1.2);
  EXPECT_EQ(apply_survey_vehicle_param(c, "speed", "0").error, "parameter speed=0 must be > 0");
  EXPECT_EQ(apply_survey_vehicle_param(c, "speed", "fast").error,
            "parameter speed='fast' is not a number");
  EXPECT_EQ(c.vehicle.speed_mps, 1.2);
  EXPECT_EQ(apply_survey_vehicle_param(c, "overlap", "1").error,
            "parameter overlap=1 must be in [0, 1)");
  EXPECT_EQ(apply_survey_vehicle_param(c, "random_seed", "-4").error,
            "parameter random_seed='-4' is not a whole number");
  EXPECT_EQ(apply_survey_vehicle_param(c, "random_seed", "42").error, "");
  EXPECT_EQ(c.vehicle.seed, 42u);
  EXPECT_EQ(apply_survey_vehicle_param(c, "lane_heading", "-30").error, "");
  EXPECT_EQ(c.lawnmower.lane_heading_deg, -30);
  EXPECT_NE(apply_survey_vehicle_param(c, "region", "0,0:1,1")
                .error.find("parameter region: polygon"),
            std::string::npos);
  EXPECT_EQ(apply_survey_vehicle_param(c, "waypoints", "pts={0,10:20,30}").error, "");
  EXPECT_EQ(c.waypoints_m.size(), 2u);
  EXPECT_EQ(apply_survey_vehicle_param(c, "wheels", "4").error, "unknown parameter 'wheels'");
  EXPECT_EQ(survey_vehicle_parameters().size(), 17u);
  EXPECT_EQ(validate(c.vehicle).error, "");
}

TEST(VehicleConfig, RouteIsTheLawnmowerWhenARegionIsGivenElseTheWaypoints) {
  SurveyVehicleConfig c;
  apply_survey_vehicle_param(c, "waypoints", "5,5:6,6");
  auto route = plan_route(c);
  ASSERT_TRUE(route) << route.error;
  EXPECT_EQ(route.value->size(), 2u);
  apply_survey_vehicle_param(c, "region", "pts={-150,-75:-150,-400:400,-400:400,-75}");  // Jake
  apply_survey_vehicle_param(c, "start_x", "-180");
  apply_survey_vehicle_param(c, "start_y", "-40");
  route = plan_route(c);
  ASSERT_TRUE(route) << route.error;
  const auto& wps = *route.value;
  // 550 m across at 45 m spacing (W 25, overlap 0.1): 13 lanes, 2 waypoints each, starting at
  // the north-west corner nearest the start.
  EXPECT_EQ(wps.size(), 26u);
  EXPECT_LT(wps[0].x, -100);
  EXPECT_GT(wps[0].y, -75);
}

TEST(Random, UniformAndNormalHaveTheirMomentsOver100000Draws) {
  constexpr int kN = 100000;
  double sum_u = 0, sum_z = 0, sum_z2 = 0;
  for (int i = 0; i < kN; ++i) {
    const double u = uniform01(3, 9, static_cast<std::uint64_t>(i));
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum_u += u;
    const double z = standard_normal(3, 10, static_cast<std::uint64_t>(i));
    sum_z += z;
    sum_z2 += z * z;
  }
  EXPECT_NEAR(sum_u / kN, 0.5, 5 * std::sqrt(1.0 / 12.0 / kN));
  EXPECT_NEAR(sum_z / kN, 0.0, 5 / std::sqrt(kN));
  EXPECT_NEAR(sum_z2 / kN, 1.0, 5 * std::sqrt(2.0 / kN));
  EXPECT_EQ(uniform01(1, 2, 3), uniform01(1, 2, 3));  // a pure function
  EXPECT_NE(uniform01(1, 2, 3), uniform01(1, 2, 4));
}

TEST(Outputs, AppendKeepsOrderAndKinds) {
  Outputs a, b;
  a.post("A", "1");
  b.post_double("B", 2.5);
  b.events.push_back("e");
  b.run_warnings.push_back("w");
  a.append(std::move(b));
  ASSERT_EQ(a.postings.size(), 2u);
  EXPECT_EQ(a.postings[1].variable, "B");
  EXPECT_EQ(*a.postings[1].number, 2.5);
  EXPECT_FALSE(a.postings[0].number.has_value());
  EXPECT_EQ(a.events.size(), 1u);
  EXPECT_EQ(a.run_warnings.size(), 1u);
}

}  // namespace
}  // namespace mission
