// Numerically delicate probabilities (differences.md D5, D27, D28): pd at 0, 1 and
// 1e-300, ROC exponents 1 and 10,000 (pfa underflows to exactly 0, never to a subnormal), hr at
// 0 and 1, pclass at 0.5 and 1, and dice exactly at their boundaries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hazard/dice.hpp"
#include "hazard/sensor_model.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::first_label;
using testing::quiet_block;

double detection_u(std::uint64_t k) { return static_cast<double>(k) / kDieResolution; }

// Every die value of the detection die (k = 0..9999) that succeeds for threshold p.
int detecting_steps(double p) {
  int n = 0;
  for (std::uint64_t k = 0; k < kDetectionDieSteps; ++k) n += detection_succeeds(detection_u(k), p);
  return n;
}

// ---- pd -----------------------------------------------------------------------------------------

TEST(NumericsProbability, PdZeroNeverDetectsAndPdOneAlwaysDetects_N7) {
  EXPECT_EQ(detecting_steps(0.0), 0);
  EXPECT_EQ(detecting_steps(1.0), 10000);
  EXPECT_EQ(roc_false_alarm_probability(0.0, 4.0), 0.0);
  EXPECT_EQ(roc_false_alarm_probability(1.0, 10000.0), 1.0);
}

TEST(NumericsProbability, PdOf1eMinus300DetectsOnlyOnTheZeroDieAndItsPfaIsZero_N5_N7) {
  EXPECT_EQ(detecting_steps(1e-300), 1);  // u = 0 < 1e-300: the original's quantisation
  EXPECT_TRUE(detection_succeeds(0.0, 1e-300));
  EXPECT_FALSE(detection_succeeds(1e-4, 1e-300));
  EXPECT_EQ(roc_false_alarm_probability(1e-300, 4.0), 0.0);  // 1e-1200: exactly 0
  EXPECT_EQ(roc_false_alarm_probability(1e-300, 1.0), 1e-300);
  Driver d(quiet_block());
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1e-300");
  const auto& s = *d.vehicle("v").setting;
  EXPECT_EQ(s.pd, 1e-300);
  EXPECT_EQ(s.pfa, 0.0);
  EXPECT_TRUE(contains(testing::values_of(d.all, "UHZ_CONFIG_ACK"), "pd=0,pfa=0,"));
}

// ---- exp ----------------------------------------------------------------------------------------

TEST(NumericsProbability, ExponentOneIsTheLinearRoc_Manual4_2) {
  for (double pd : {0.0, 1e-300, 0.3, 0.9, 1.0}) EXPECT_EQ(roc_false_alarm_probability(pd, 1.0), pd);
}

TEST(NumericsProbability, ExponentTenThousandUnderflowsToExactlyZeroNeverSubnormal_N5) {
  EXPECT_EQ(roc_false_alarm_probability(0.9, 10000.0), 0.0);   // 1e-458: below every double
  EXPECT_EQ(roc_false_alarm_probability(0.93, 10000.0), 0.0);  // 1e-315: a subnormal, flushed
  EXPECT_NEAR(roc_false_alarm_probability(0.9999, 10000.0), std::exp(-1.00005), 1e-4);
  // No pd gives a subnormal pfa at any exponent: subnormal operands make every later add and
  // compare take a microcode assist (about 100 times slower on x86).
  for (double e : {1.0, 2.0, 4.0, 100.0, 10000.0}) {
    for (double pd = 1e-320; pd < 1.0; pd = pd * 1.37 + 1e-320) {
      EXPECT_NE(std::fpclassify(roc_false_alarm_probability(pd, e)), FP_SUBNORMAL)
          << pd << "^" << e;
    }
  }
  // The degraded exponent of an aspect object stays in [1, exp] (D5), so exp' = 1 at g = 1.
  EXPECT_EQ(degraded_exponent(10000.0, 1.0), 1.0);
  EXPECT_EQ(degraded_exponent(10000.0, 0.0), 10000.0);
}

TEST(NumericsProbability, ExponentTenThousandIsAValidOptionWithPfaZeroInTheAck_N5) {
  Driver d(quiet_block("sensor_config = width=50, exp=10000, pclass=1\n"));
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=50,pd=0.9");
  EXPECT_EQ(d.vehicle("v").setting->exp, 10000.0);
  EXPECT_EQ(d.vehicle("v").setting->pfa, 0.0);
  EXPECT_EQ(testing::values_of(d.all, "UHZ_CONFIG_ACK").back(),
            "vname=v,width=50,pd=0.9,pfa=0,pclass=1");
  EXPECT_TRUE(d.engine.invariant_violations().empty());
}

// ---- hr ------------------------------------------------------------------------------------------

TEST(NumericsProbability, ResemblanceZeroHalvesPfaAndOneMeetsItHalfway_Manual6_N8) {
  EXPECT_EQ(resemblance_false_alarm_probability(0.6561, 0.0), 0.6561 / 2);
  EXPECT_EQ(resemblance_false_alarm_probability(0.0, 0.0), 0.0);
  EXPECT_EQ(resemblance_false_alarm_probability(0.0, 1.0), 0.5);
  EXPECT_EQ(resemblance_false_alarm_probability(1.0, 1.0), 1.0);
  // Classification: hr = 1 leaves pc as it is, hr = 0 makes a benign object always right.
  EXPECT_EQ(resemblance_classification_probability(0.8, 1.0), 0.8);
  EXPECT_EQ(resemblance_classification_probability(0.8, 0.0), 1.0);
  EXPECT_EQ(resemblance_classification_probability(0.5, 0.0), 1.0);
}

// ---- pclass --------------------------------------------------------------------------------------

TEST(NumericsProbability, PclassHalfIsACoinAtAnyAspectAndOneIsAlwaysRight_Manual7_2_D27) {
  for (double g : {0.0, 0.3, 1.0}) EXPECT_EQ(aspect_classification_probability(0.5, g), 0.5);
  EXPECT_EQ(aspect_classification_probability(1.0, 0.0), 1.0);
  EXPECT_EQ(aspect_classification_probability(1.0, 1.0), 0.5);
  // pclass 1: correct for every die value, the largest (v = 1) included.
  EXPECT_TRUE(classification_correct(1.0, 1.0));
  // pclass 0.5: v <= 0.5 is k <= 5000, 5001 of the 10001 values.
  EXPECT_DOUBLE_EQ(classification_success_probability(0.5), 5001.0 / 10001.0);
  Driver ok("sensor_config = width=5, exp=1, pclass=0.5\nsensor_config = width=6, exp=1, pclass=1\n"
            "sensor_config = width=7, exp=1, pclass=0.4999\n"
            "sensor_config = width=8, exp=1, pclass=1.0001\n");
  EXPECT_EQ(ok.engine.config().options.size(), 2u);
  EXPECT_TRUE(contains(ok.all.config_warnings, "pclass=0.4999"));
  EXPECT_TRUE(contains(ok.all.config_warnings, "pclass=1.0001"));
}

// ---- dice exactly at their boundaries (N7) -----------------------------------------------------------

TEST(NumericsProbability, DetectionAtExactlyTheThresholdFailsAndOneStepBelowSucceeds_N7) {
  // The die u = k / 10000 and a threshold written with four decimals are the same double, so the
  // boundary is exact: u < p.
  for (const auto& [text, k] : std::vector<std::pair<const char*, std::uint64_t>>{
           {"0.6561", 6561}, {"0.9", 9000}, {"0.25", 2500}, {"0.0001", 1}, {"0.9999", 9999}}) {
    const double p = *base::parse_number(text);
    EXPECT_FALSE(detection_succeeds(detection_u(k), p)) << text;
    EXPECT_TRUE(detection_succeeds(detection_u(k - 1), p)) << text;
    EXPECT_EQ(detecting_steps(p), static_cast<int>(k)) << text;
  }
  // A computed threshold decides by its representation: 0.1 * 3 = 0.30000000000000004 admits
  // the die 0.3 that the written 0.3 does not.
  EXPECT_EQ(detecting_steps(0.1 * 3), 3001);
  EXPECT_EQ(detecting_steps(0.3), 3000);
}

TEST(NumericsProbability, ClassificationAtExactlyTheThresholdSucceedsAndOneStepAboveFails_N7) {
  for (const auto& [text, k] : std::vector<std::pair<const char*, std::uint64_t>>{
           {"0.5", 5000}, {"0.8", 8000}, {"1", 10000}, {"0.0001", 1}}) {
    const double p = *base::parse_number(text);
    EXPECT_TRUE(classification_correct(static_cast<double>(k) / kDieResolution, p)) << text;
    if (k < 10000) {
      EXPECT_FALSE(classification_correct(static_cast<double>(k + 1) / kDieResolution, p)) << text;
    }
  }
}

TEST(NumericsProbability, EngineDetectsAHazardOneDieStepBelowPdAndNotAtIt_N7) {
  // Objects whose pass-1 detection die is exactly pd (0.9) and one step below it.
  const std::string at = first_label(1, "v", "at", [](double u, double) { return u == 0.9; });
  const std::string below =
      first_label(1, "v", "below", [](double u, double) { return u == 0.8999; });
  Driver d(quiet_block("hazard = x=0,y=0,label=" + at + ",type=hazard\nhazard = x=1,y=0,label=" +
                       below + ",type=hazard\n"));
  d.sense_at_origin("v", "25", "0.9");
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 2);
  EXPECT_EQ(testing::values_of(d.all, "UHZ_DETECTION_REPORT"),
            std::vector<std::string>{"vname=v,x=1,y=0,label=" + below});
}

TEST(NumericsProbability, EngineClassifiesCorrectlyAtADieEqualToPclass_N7) {
  // pclass 0.8: a die of exactly 0.8 is a correct answer, 0.8001 a wrong one.
  const std::string at =
      first_label(1, "v", "c", [](double u, double v) { return u < 0.9 && v == 0.8; });
  const std::string above =
      first_label(1, "v", "w", [](double u, double v) { return u < 0.9 && v == 0.8001; });
  Driver d(quiet_block("hazard = x=0,y=0,label=" + at + ",type=hazard\nhazard = x=1,y=0,label=" +
                       above + ",type=hazard\n"));
  d.sense_at_origin("v", "25", "0.9");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + at);
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + above);
  d.tick_at(1);
  d.tick_at(2);
  EXPECT_EQ(testing::values_of(d.all, "UHZ_HAZARD_REPORT"),
            (std::vector<std::string>{"vname=v,x=0,y=0,label=" + at + ",type=hazard",
                                      "vname=v,x=1,y=0,label=" + above + ",type=benign"}));
}

}  // namespace
}  // namespace hazard
