// Turn rate (manual 8).
#include <gtest/gtest.h>

#include "hazard/heading_history.hpp"

namespace hazard {
namespace {

TEST(HeadingHistory, SpecExampleWrapsAcrossNorth_T5) {
  HeadingHistory h;
  h.add(350, 0.0);
  h.add(355, 0.5);
  h.add(5, 1.0);
  h.add(10, 1.5);
  EXPECT_NEAR(h.turn_rate_dps(), 20.0 / 1.5, 1e-12);
}

TEST(HeadingHistory, OneSampleOrNoTimeIsZero_N4) {
  HeadingHistory h;
  EXPECT_EQ(h.turn_rate_dps(), 0.0);
  h.add(90, 3.0);
  EXPECT_EQ(h.turn_rate_dps(), 0.0);
  h.add(180, 3.0);  // same time: ignored
  EXPECT_EQ(h.size(), 1u);
  EXPECT_EQ(h.turn_rate_dps(), 0.0);
  h.add(100, 2.0);  // older: ignored
  EXPECT_EQ(h.size(), 1u);
}

TEST(HeadingHistory, WindowIsTwoSecondsStrictAnchoredAtNewest) {
  HeadingHistory h;
  h.add(0, 0.0);
  h.add(90, 1.0);  // 90 deg in 1 s
  EXPECT_NEAR(h.turn_rate_dps(), 90.0, 1e-12);
  h.add(90, 2.0);  // the 0.0 sample is exactly 2 s old: outside (strict)
  EXPECT_NEAR(h.turn_rate_dps(), 0.0, 1e-12);
  EXPECT_EQ(h.size(), 2u);
  h.add(91, 3.9);
  EXPECT_NEAR(h.turn_rate_dps(), 1.0 / 1.9, 1e-12);
}

TEST(HeadingHistory, JitterAccumulates_N4) {
  HeadingHistory h;
  for (int i = 0; i < 8; ++i) h.add(i % 2 ? 91 : 89, i * 0.25);  // +-1 deg at 4 Hz
  EXPECT_GT(h.turn_rate_dps(), 1.5);  // above the default max_turn_rate
}

TEST(HeadingHistory, HalfTurnStepCountsOneEighty_N4) {
  HeadingHistory h;
  h.add(0, 0.0);
  h.add(180, 1.0);
  EXPECT_NEAR(h.turn_rate_dps(), 180.0, 1e-12);
}

TEST(HeadingHistory, MemoryIsBounded) {
  HeadingHistory h;
  for (int i = 0; i < 5000; ++i) h.add(0, i * 1e-4);
  EXPECT_LE(h.size(), HeadingHistory::kMaxSamples);
}

}  // namespace
}  // namespace hazard
