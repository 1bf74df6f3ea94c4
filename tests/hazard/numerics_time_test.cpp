// Epoch-scale times (differences.md D9, D11, D12, "Release timing"; N11): a day of
// iterations at 1.8e9 s under time warp 100 with AppTick 3, whose iteration times carry the
// rounding of a warped wall clock (2.4e-5 s). Every interval rule must fire at the same
// iteration every time: min_classify_interval, min_reset_interval, the 600 s sensor window, the
// 2 s turn window and the options summary neither drift (slip a tick per period) nor skip.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "hazard/time_rules.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::node_report;
using testing::setup_from;

constexpr double kEpoch_s = 1.8e9;      // MOOS time at start-up
constexpr double kWallEpoch_s = 1.7e9;  // the wall clock at start-up
constexpr double kWarp = 100.0;
constexpr double kAppTick_hz = 3.0;     // 1/3 s: not a binary fraction
constexpr long kIterationsPerDay = 24L * 3600L * 3L;

// The MOOS time of iteration k as an app computes it: wall-clock cycles 1/(AppTick * warp) real
// seconds apart, MOOS time = epoch + warp * (wall - wall epoch).
double moos_time(long k) {
  const double wall_s = kWallEpoch_s + static_cast<double>(k) * (1.0 / (kAppTick_hz * kWarp));
  return kEpoch_s + kWarp * (wall_s - kWallEpoch_s);
}

TEST(NumericsTime, WarpedEpochClockCarriesRoundingThatExactComparisonsWouldMisread) {
  // The premise: some 90-iteration spans (30 s in exact arithmetic) come out short of 30 s.
  int short_spans = 0;
  for (long k = 0; k + 90 < 100000; k += 90) short_spans += moos_time(k + 90) - moos_time(k) < 30.0;
  EXPECT_GT(short_spans, 0);
  for (long k = 0; k < 1000; ++k) {
    EXPECT_LT(std::fabs(moos_time(k + 90) - moos_time(k) - 30.0), clock_tolerance_s(moos_time(k)));
  }
}

struct DayCounts {
  std::vector<long> releases;        // iterations with a UHZ_HAZARD_REPORT
  std::vector<long> width_changes;   // iterations at which the width changed
  std::vector<long> summaries;       // iterations with a UHZ_OPTIONS_SUMMARY
  std::map<long, int> sensing_per_period;  // VIEW_POLYGON postings per 2000 iterations
  long wrong_turn_window = 0;        // iterations whose 2 s heading window did not hold 6 samples
};

DayCounts run_day() {
  hazard::Driver driver(setup_from(testing::quiet_block(
                    "sensor_config = width=10, exp=2, pclass=0.9\n"
                    "hazard = x=0,y=0,label=a,type=hazard\n"
                    "max_turn_rate = 1.5\nmin_classify_interval = 30\nmin_reset_interval = 300\n"
                    "options_summary_interval = 10\nshow_swath = true\n")),
                SeedChoice{5, SeedSource::kCommandLine});
  driver.start(moos_time(0));
  DayCounts c;
  double width_m = 0.0;
  for (long k = 0; k < kIterationsPerDay; ++k) {
    const double now = moos_time(k);
    // The vehicle hops on and off the object (an entry every other iteration), asks for the
    // other width every iteration, a classification every iteration, and the sensor every
    // 2000 iterations (666.7 s: on for 600 s, then off).
    driver.deliver(Mail{"NODE_REPORT", node_report("v", k % 2 ? 100.0 : 0.0, 0.0, 90.0), now});
    if (k % 2000 == 0) driver.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", now});
    const std::string other = width_m == 25.0 ? "10" : "25";
    driver.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=v,pd=1,width=" + other, now});
    driver.deliver(Mail{"UHZ_CLASSIFY_REQUEST", "vname=v,label=a", now});
    const Outputs out = driver.step(now).outputs;
    for (const Posting& p : out.postings) {
      if (p.variable == "UHZ_HAZARD_REPORT") c.releases.push_back(k);
      if (p.variable == "UHZ_OPTIONS_SUMMARY") c.summaries.push_back(k);
      if (p.variable == "VIEW_POLYGON") ++c.sensing_per_period[k / 2000];
    }
    const VehicleState& v = driver.engine().vehicle(0);
    if (v.setting && v.setting->width_m != width_m) {
      width_m = v.setting->width_m;
      c.width_changes.push_back(k);
    }
    if (k >= 5 && v.heading_history->size() != 6) ++c.wrong_turn_window;
  }
  EXPECT_TRUE(driver.engine().invariant_violations().empty());
  return c;
}

// Differences between consecutive entries that are not `period`, as "index:difference".
std::vector<std::string> off_period(const std::vector<long>& at, long period) {
  std::vector<std::string> bad;
  for (std::size_t i = 1; i < at.size(); ++i) {
    if (at[i] - at[i - 1] != period) {
      bad.push_back(std::to_string(at[i - 1]) + ":" + std::to_string(at[i] - at[i - 1]));
    }
  }
  return bad;
}

TEST(NumericsTime, IntervalsAtEpochTimesUnderWarp100NeitherDriftNorSkipForADay) {
  const DayCounts c = run_day();
  // min_classify_interval 30 s = 90 iterations, from the first answer at iteration 1.
  ASSERT_FALSE(c.releases.empty());
  EXPECT_EQ(c.releases.front(), 1);
  EXPECT_TRUE(off_period(c.releases, 90).empty()) << off_period(c.releases, 90).front();
  EXPECT_EQ(c.releases.size(), static_cast<std::size_t>((kIterationsPerDay - 2) / 90 + 1));
  // min_reset_interval 300 s = 900 iterations.
  EXPECT_EQ(c.width_changes.front(), 0);
  EXPECT_TRUE(off_period(c.width_changes, 900).empty()) << off_period(c.width_changes, 900).front();
  EXPECT_EQ(c.width_changes.size(), static_cast<std::size_t>(kIterationsPerDay / 900));
  // options_summary_interval 10 s = 30 iterations.
  EXPECT_TRUE(off_period(c.summaries, 30).empty()) << off_period(c.summaries, 30).front();
  EXPECT_EQ(c.summaries.size(), static_cast<std::size_t>(kIterationsPerDay / 30));
  // The 600 s sensor window: exactly 1800 sensing iterations after each request.
  for (const auto& [period, n] : c.sensing_per_period) {
    if ((period + 1) * 2000 <= kIterationsPerDay) {
      EXPECT_EQ(n, 1800) << "period " << period;
    }
  }
  EXPECT_EQ(c.sensing_per_period.size(), static_cast<std::size_t>(kIterationsPerDay / 2000 + 1));
  // The 2 s turn window: the samples of the last 2 s (strict) are always exactly 6.
  EXPECT_EQ(c.wrong_turn_window, 0);
}

TEST(NumericsTime, AnIntervalIsReachedWithinTheClocksRoundingAndNotBefore) {
  EXPECT_TRUE(elapsed_at_least(kEpoch_s + 30.0, kEpoch_s, 30.0));
  EXPECT_TRUE(elapsed_at_least(kEpoch_s + 29.99998, kEpoch_s, 30.0));  // 2e-5 s short: rounding
  EXPECT_FALSE(elapsed_at_least(kEpoch_s + 29.9999, kEpoch_s, 30.0));  // 1e-4 s short: not yet
  EXPECT_FALSE(elapsed_at_least(29.99998, 0.0, 30.0));  // a clock near 0 has no rounding to forgive
  EXPECT_TRUE(elapsed_at_least(5.0, 5.0, 0.0));         // a zero interval is always reached
}

}  // namespace
}  // namespace hazard
