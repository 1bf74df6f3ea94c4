// The model formulas as free functions (manual 4.2, 6, 7; differences.md D5, D6).
#include <gtest/gtest.h>

#include "hazard/sensor_model.hpp"

namespace hazard {
namespace {

TEST(SensorModel, RocIsPdToTheExp_Manual4_2) {
  EXPECT_DOUBLE_EQ(roc_false_alarm_probability(0.9, 4), 0.6561);
  EXPECT_DOUBLE_EQ(roc_false_alarm_probability(0.9, 1), 0.9);
  EXPECT_NEAR(roc_false_alarm_probability(0.95, 12), 0.5403600876626367, 1e-15);  // D23
  EXPECT_EQ(roc_false_alarm_probability(0.0, 4), 0.0);
  EXPECT_EQ(roc_false_alarm_probability(1.0, 20), 1.0);
}

TEST(SensorModel, ResemblanceAveragesWithPfa_Manual6_1_T4) {
  EXPECT_DOUBLE_EQ(resemblance_false_alarm_probability(0.6561, 0.73), 0.69305);
  EXPECT_DOUBLE_EQ(resemblance_false_alarm_probability(0.6561, 0.0), 0.32805);  // hr = 0 halves
}

TEST(SensorModel, AspectDifferenceIsAnAxisAngle_Manual7) {
  EXPECT_DOUBLE_EQ(aspect_difference_deg(57, 57), 0);
  EXPECT_DOUBLE_EQ(aspect_difference_deg(57 + 180, 57), 0);  // either direction
  EXPECT_DOUBLE_EQ(aspect_difference_deg(90, 0), 90);
  EXPECT_DOUBLE_EQ(aspect_difference_deg(350, 10), 20);       // wraps
  EXPECT_DOUBLE_EQ(aspect_difference_deg(100, 0), 80);
  EXPECT_DOUBLE_EQ(aspect_difference_deg(-30, 330), 0);
}

TEST(SensorModel, DegradationIsAFraction_D6) {
  EXPECT_EQ(aspect_degradation(10, 20, 45), 0.0);
  EXPECT_EQ(aspect_degradation(20, 20, 45), 0.0);
  EXPECT_DOUBLE_EQ(aspect_degradation(32.5, 20, 45), 0.5);
  EXPECT_EQ(aspect_degradation(45, 20, 45), 1.0);
  EXPECT_EQ(aspect_degradation(80, 20, 45), 1.0);
  EXPECT_EQ(aspect_degradation(30, 30, 30), 0.0);  // min == max: no division (N6)
  EXPECT_EQ(aspect_degradation(30.1, 30, 30), 1.0);
}

TEST(SensorModel, DegradedRocMovesTowardLinear_Manual7_1_T4) {
  EXPECT_DOUBLE_EQ(degraded_exponent(5, 0.5), 3);  // manual's example
  EXPECT_DOUBLE_EQ(degraded_exponent(5, 1.0), 1);
  EXPECT_DOUBLE_EQ(degraded_exponent(5, 0.0), 5);
  EXPECT_NEAR(roc_false_alarm_probability(0.9, degraded_exponent(5, 0.5)), 0.729, 1e-12);
}

TEST(SensorModel, ClassificationProbabilities_Manual6_2_7_2_T6) {
  const double pc1 = resemblance_classification_probability(0.8, 0.3);
  EXPECT_DOUBLE_EQ(pc1, 0.94);
  EXPECT_DOUBLE_EQ(aspect_classification_probability(pc1, 0.5), 0.72);
  EXPECT_DOUBLE_EQ(resemblance_classification_probability(0.8, 1.0), 0.8);  // R = 1: lowest
  EXPECT_DOUBLE_EQ(resemblance_classification_probability(0.8, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(aspect_classification_probability(0.9, 1.0), 0.5);  // full degradation
}

TEST(SensorModel, DiceBoundaries_N7) {
  // Detection: strict '<' -> p = 0.6561 admits u = 0.656 but not 0.6561.
  EXPECT_TRUE(detection_succeeds(0.6560, 0.6561));
  EXPECT_FALSE(detection_succeeds(0.6561, 0.6561));
  EXPECT_TRUE(detection_succeeds(0.9999, 1.0));  // pd 1 always detects
  EXPECT_FALSE(detection_succeeds(0.0, 0.0));     // pd 0 never
  // Classification: '<=' -> pc'' = 1 always correct, 0 only at v = 0.
  EXPECT_TRUE(classification_correct(1.0, 1.0));
  EXPECT_TRUE(classification_correct(0.0, 0.0));
  EXPECT_FALSE(classification_correct(0.0001, 0.0));
  EXPECT_FALSE(classification_correct(0.85, 0.72));  // T6: reported wrong
}

}  // namespace
}  // namespace hazard
