// Numerically delicate angles (differences.md "Numbers", "Defects we fix"): the
// 0/360 seam in turn rate and aspect, huge and negative headings, non-finite input, and the edges
// of the aspect window. Each test name states the rule it pins.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hazard/heading_history.hpp"
#include "hazard/messages/hazard_line.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/sensor_model.hpp"
#include "hazard/swath.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::quiet_block;

constexpr double kExact = 1e-12;  // deg: differences of degree values near 360 carry ~6e-14

// ---- the 0/360 seam ------------------------------------------------------------------------------

TEST(NumericsAngles, TurnRateAcrossTheSeamIsTheShortStep_359_9To0_1_N4) {
  HeadingHistory up;
  up.add(359.9, 0.0);
  up.add(0.1, 1.0);
  EXPECT_NEAR(up.turn_rate_dps(), 0.2, kExact);
  HeadingHistory down;
  down.add(0.1, 0.0);
  down.add(359.9, 1.0);
  EXPECT_NEAR(down.turn_rate_dps(), 0.2, kExact);
}

TEST(NumericsAngles, OscillatingAcrossNorthKeepsTheSensorOnBelowTheTurnLimit_N4) {
  // 359.9 <-> 0.1 at 4 Hz is 0.2 deg per 0.25 s = 0.8 deg/s, below the default 1.5: sensing goes
  // on; a heading normaliser that took the long way (359.8 deg steps) would black it out.
  Driver d(quiet_block("max_turn_rate = 1.5\nhazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  for (int k = 0; k < 12; ++k) {
    d.pose("v", 0, -100, k % 2 ? 0.1 : 359.9);
    d.tick_at(k * 0.25);
  }
  EXPECT_LT(d.vehicle("v").heading_history->turn_rate_dps(), 1.0);
  d.pose("v", 0, 0, 0.1);
  d.tick_at(3.0);
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 1);  // sensed: the object entered
}

TEST(NumericsAngles, AspectDifferenceAcrossTheSeamIsTheShortAngle_Manual7) {
  EXPECT_NEAR(aspect_difference_deg(359.9, 0.1), 0.2, kExact);
  EXPECT_NEAR(aspect_difference_deg(0.1, 359.9), 0.2, kExact);
  // An axis: approaching from the opposite direction is the same aspect.
  EXPECT_NEAR(aspect_difference_deg(179.9, 0.1), 0.2, kExact);
  EXPECT_NEAR(aspect_difference_deg(0.0, 359.99), 0.01, kExact);
  EXPECT_NEAR(aspect_difference_deg(179.99, 359.99), 0.0, kExact);
  EXPECT_NEAR(aspect_difference_deg(90.0, 0.0), 90.0, kExact);  // the largest difference
}

// ---- huge and negative headings (N3) -------------------------------------------------------------

TEST(NumericsAngles, HugeAndNegativeHeadingsNormaliseExactlyInOneStep_N3) {
  // fmod is exact: 1e6 = 2777 * 360 + 280, and 1e15 = 10^15 mod 360 = 280 as well.
  EXPECT_EQ(base::norm360(-720.0), 0.0);
  EXPECT_FALSE(std::signbit(base::norm360(-720.0)));  // +0, not -0
  EXPECT_EQ(base::norm360(1e6), 280.0);
  EXPECT_EQ(base::norm360(1e15), 280.0);
  EXPECT_EQ(base::norm360(-1e15), 80.0);
  EXPECT_EQ(base::norm360(-1e-17), 0.0);  // -1e-17 + 360 rounds to 360: mapped to 0
  const double far = base::norm360(1e300);  // above 2^53 subtracting 360 no longer changes the value:
  EXPECT_GE(far, 0.0);                // the original's loop never ended there
  EXPECT_LT(far, 360.0);
  EXPECT_EQ(base::norm180(-180.0), 180.0);
  EXPECT_EQ(base::norm180(540.0), 180.0);
}

TEST(NumericsAngles, HugeHeadingsInNodeReportsAreNormalisedAtParseTime_N3) {
  for (const auto& [text, expected] : std::vector<std::pair<std::string, double>>{
           {"-720", 0.0}, {"1e6", 280.0}, {"1e15", 280.0}, {"1000000000000000", 280.0},
           {"-90", 270.0}, {"359.99", 359.99}}) {
    const auto r = parse_node_report("NAME=v,X=0,Y=0,SPD=1,HDG=" + text);
    ASSERT_TRUE(r) << text;
    EXPECT_EQ(r.value->heading_deg, expected) << text;
  }
}

TEST(NumericsAngles, ASwathAtHeading1e15IsTheSwathAt280) {
  const auto a = Swath({3, 4}, 1e15, 25, 5).corners();
  const auto b = Swath({3, 4}, 280, 25, 5).corners();
  for (int i = 0; i < 4; ++i) EXPECT_EQ(a[i], b[i]) << i;
}

// ---- non-finite input (differences.md "Numbers") ------------------------------------------------

TEST(NumericsAngles, NanAndInfinityAreRejectedAtParseTimeWithAWarning) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  for (const char* bad : {"HDG=nan", "HDG=inf", "HDG=-inf", "HDG=1e999", "HDG=NaN"}) {
    const Outputs out = d.mail("NODE_REPORT", std::string("NAME=v,X=0,Y=0,SPD=1,") + bad);
    ASSERT_EQ(out.run_warnings.size(), 1u) << bad;
    EXPECT_TRUE(contains(out.run_warnings, "field 'HDG'")) << out.run_warnings[0];
    EXPECT_TRUE(contains(out.run_warnings, "is not a finite number")) << out.run_warnings[0];
  }
  for (const char* bad : {"X=nan", "Y=inf", "SPD=1e400"}) {
    const Outputs out = d.mail("NODE_REPORT", std::string("NAME=v,X=0,Y=0,SPD=1,HDG=0,") + bad);
    EXPECT_EQ(out.run_warnings.size(), 1u) << bad;
  }
  EXPECT_FALSE(d.engine.find_vehicle("v")) << "no report was applied";
  for (const char* bad : {"aspect=nan", "aspect_min=inf", "hr=nan", "x=1e999"}) {
    const HazardLineParse p =
        parse_hazard_line(std::string("x=0,y=0,label=a,type=benign,aspect=10,") + bad);
    EXPECT_FALSE(p.object) << bad;
    EXPECT_NE(p.error.find("is not a number"), std::string::npos) << p.error;
  }
  Driver config("max_turn_rate = inf\nmax_vehicle_speed = nan\nswath_length = 1e999\n");
  EXPECT_EQ(config.all.config_warnings.size(), 5u);  // 3 values + no field + no options
  EXPECT_TRUE(contains(config.all.config_warnings, "parameter 'max_turn_rate' value 'inf'"));
  EXPECT_EQ(config.engine.config().max_turn_rate_dps, 1.5);  // the default stays
}

// ---- the aspect window (N6) -------------------------------------------------------------------------

TEST(NumericsAngles, AspectMinEqualToMaxIsAStepWithoutDividing_N6) {
  EXPECT_EQ(aspect_degradation(19.999, 20, 20), 0.0);
  EXPECT_EQ(aspect_degradation(20.0, 20, 20), 0.0);  // <= min: full performance
  EXPECT_EQ(aspect_degradation(20.001, 20, 20), 1.0);
  EXPECT_EQ(aspect_degradation(0.0, 0, 0), 0.0);
  EXPECT_EQ(aspect_degradation(1e-300, 0, 0), 1.0);
  const HazardLineParse p = parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=10,"
                                              "aspect_min=20,aspect_max=20");
  ASSERT_TRUE(p.object) << p.error;
  EXPECT_TRUE(p.object->has_aspect_triple());
}

TEST(NumericsAngles, AspectMaxNinetyDegradesLinearlyOverTheQuarterTurn_N6) {
  EXPECT_EQ(aspect_degradation(0.0, 0, 90), 0.0);
  EXPECT_EQ(aspect_degradation(45.0, 0, 90), 0.5);
  EXPECT_EQ(aspect_degradation(90.0, 0, 90), 1.0);  // the largest difference is fully degraded
  ASSERT_TRUE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=1,aspect_min=0,"
                                "aspect_max=90").object);
  EXPECT_FALSE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=1,aspect_min=0,"
                                 "aspect_max=90.000001").object);
}

TEST(NumericsAngles, AspectZeroAnd359_99AreValidAnd360IsNot_D27) {
  ASSERT_TRUE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=0").object);
  ASSERT_TRUE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=359.99").object);
  EXPECT_FALSE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=360").object);
  EXPECT_FALSE(parse_hazard_line("x=0,y=0,label=a,type=benign,aspect=-0.01").object);
  // 359.99 is 0.01 deg from north; aspect 0 is the north-south axis.
  EXPECT_NEAR(aspect_difference_deg(0.0, 359.99), 0.01, kExact);
  EXPECT_NEAR(aspect_difference_deg(180.0, 0.0), 0.0, kExact);
  EXPECT_EQ(aspect_degradation(aspect_difference_deg(180.0, 0.0), 0, 10), 0.0);
}

}  // namespace
}  // namespace hazard
