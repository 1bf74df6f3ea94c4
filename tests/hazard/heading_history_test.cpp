// Turn rate (manual 8).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "base/text.hpp"
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

// The rate is the in-order sum of the window's steps over its span, double for double, whether
// the window is all straight (no sum taken) or holds a turn: legs, turns, jitter and pauses,
// with the storage reclaimed many times over.
TEST(HeadingHistory, RateIsTheInOrderSumOverStraightsAndTurns) {
  HeadingHistory h;
  std::vector<std::pair<double, double>> samples;  // (time, heading) added
  double heading = 90.0;
  for (int i = 0; i < 3000; ++i) {
    const double t = i * 0.1;
    const int phase = (i / 40) % 4;  // straight, turn, straight, jitter
    if (phase == 1) heading = base::norm360(heading + 7.5);
    if (phase == 3) heading = (i % 2) ? 90.25 : 89.75;
    if (phase == 2 && i % 40 == 0) heading = 180.0;
    h.add(heading, t);
    samples.emplace_back(t, heading);
    std::size_t first = samples.size() - 1;
    while (first > 0 && !(t - samples[first - 1].first >= HeadingHistory::kTurnWindow_s -
                                                                std::fabs(t) * 0x1p-45)) {
      --first;
    }
    double sum = 0.0;
    for (std::size_t k = first + 1; k < samples.size(); ++k) {
      sum += std::fabs(base::norm180(samples[k].second - samples[k - 1].second));
    }
    const double span = t - samples[first].first;
    const double expected = span > 0.0 ? sum / span : 0.0;
    ASSERT_EQ(h.turn_rate_dps(), expected) << "sample " << i;
    ASSERT_FALSE(std::signbit(h.turn_rate_dps())) << "sample " << i;
  }
}

TEST(HeadingHistory, MemoryIsBounded) {
  HeadingHistory h;
  for (int i = 0; i < 5000; ++i) h.add(0, i * 1e-4);
  EXPECT_LE(h.size(), HeadingHistory::kMaxSamples);
}

}  // namespace
}  // namespace hazard
