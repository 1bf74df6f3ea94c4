// Engine::quiet_until_s (src/hazard/quiet_time.cpp): until when steps would do nothing, so that
// an app may skip them (IdleAppTick). The promise is checked directly: steps before the quiet
// time post nothing, and a twin engine that skips them posts exactly what the stepping one posts.
#include <gtest/gtest.h>

#include "scenario.hpp"

namespace hazard {
namespace {

using testing::quiet_block;

constexpr double kSummaryInterval_s = 10.0;  // options_summary_interval's default

std::string block_with_objects(std::string_view extra = {}) {
  return quiet_block(std::string("hazard = x=5,y=20,label=a,type=hazard\n"
                                 "hazard = x=-5,y=40,label=b,type=benign\n") +
                     std::string(extra));
}

TEST(QuietTime, AFreshEngineIsQuietUntilTheNextOptionsSummary) {
  testing::Driver d(block_with_objects(), {}, 1, 100.0);
  EXPECT_EQ(d.engine.quiet_until_s(100.0), 100.0);  // the first summary is due now
  d.tick_at(100.0);
  EXPECT_EQ(d.engine.quiet_until_s(100.25), 100.0 + kSummaryInterval_s);
}

TEST(QuietTime, AnActiveSensorKeepsTheEngineBusyForItsWholeWindow) {
  testing::Driver d(block_with_objects(), {}, 1, 0.0);
  d.tick_at(0.0);
  d.pose("v", 0, 0);
  d.sensor_on("v");
  EXPECT_EQ(d.engine.quiet_until_s(1.0), 1.0);
  EXPECT_EQ(d.engine.quiet_until_s(599.0), 599.0);  // the request keeps it on for 600 s (D12)
  d.tick_at(600.0);  // the window has passed: inactive, and the summary was just posted
  EXPECT_EQ(d.engine.quiet_until_s(600.0), 600.0 + kSummaryInterval_s);
}

TEST(QuietTime, AQueuedAnswerKeepsTheEngineBusy) {
  testing::Driver d(block_with_objects("min_classify_interval = 30\n"), {}, 1, 0.0);
  d.sense_at_origin("v", "25", "1");
  d.pose("v", 0, 20);
  d.tick_at(0.5);
  d.pose("v", 0, 40);
  d.tick_at(1.0);  // both objects detected (pd 1, pfa 1)
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=a");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=b");
  d.tick_at(700.0);  // the sensor window has passed; one answer left in the queue
  ASSERT_FALSE(d.engine.vehicle(0).queue.empty());
  EXPECT_EQ(d.engine.quiet_until_s(701.0), 701.0);
}

TEST(QuietTime, PendingFieldVisualsKeepTheEngineBusy) {
  std::string objects;
  for (int i = 0; i < 4500; ++i) {  // more than two batches (kFieldVisualsPerIteration)
    objects += "hazard = x=" + std::to_string(i) + ",y=0,label=o" + std::to_string(i) +
               ",type=hazard\n";
  }
  testing::Driver d(quiet_block(objects + "show_hazards = true\n"), {}, 1, 0.0);
  ASSERT_GT(d.engine.field_visuals_pending(), 0u);
  d.tick_at(0.0);
  EXPECT_EQ(d.engine.quiet_until_s(0.25), 0.25);
  while (d.engine.field_visuals_pending() > 0) d.tick_at(d.now + 0.25);
  EXPECT_GT(d.engine.quiet_until_s(d.now + 0.25), d.now + 0.25);
}

// The promise itself: a twin that skips every step before the quiet time (as IdleAppTick does)
// posts exactly what the engine that steps every 0.25 s posts, at the same times.
TEST(QuietTime, SkippingTheQuietStepsChangesNothing) {
  const std::string block = block_with_objects("show_detections = 5\n");
  testing::Driver every(block, {}, 3, 0.0);
  testing::Driver skipping(block, {}, 3, 0.0);
  auto mail_at = [](int k) -> std::vector<std::pair<std::string, std::string>> {
    if (k == 40) return {{"UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=0.8"}, {"UHZ_SENSOR_REQUEST", "vname=v"}};
    if (k >= 40 && k <= 400 && k % 8 == 0)
      return {{"NODE_REPORT", testing::node_report("v", 0, (k - 40) / 8.0)}};
    if (k == 420) return {{"UHZ_CLASSIFY_REQUEST", "vname=v,label=a"}};
    return {};
  };
  std::size_t skipped = 0;
  for (int k = 0; k <= 4000; ++k) {  // 1000 s at AppTick 4
    const double t = k * 0.25;
    every.now = skipping.now = t;
    const auto mail = mail_at(k);
    for (const auto& [var, value] : mail) {
      every.mail(var, value);
      skipping.mail(var, value);
    }
    every.tick();
    if (mail.empty() && skipping.engine.quiet_until_s(t) > t) {
      ++skipped;
      continue;
    }
    skipping.tick();
  }
  EXPECT_GT(skipped, 1500u);  // the sensor window ends at 610 s; the rest is quiet
  EXPECT_FALSE(testing::values_of(every.all, "UHZ_HAZARD_REPORT").empty());
  ASSERT_EQ(skipping.all.postings.size(), every.all.postings.size());
  for (std::size_t i = 0; i < every.all.postings.size(); ++i) {
    EXPECT_EQ(skipping.all.postings[i].variable, every.all.postings[i].variable) << i;
    EXPECT_EQ(skipping.all.postings[i].value, every.all.postings[i].value) << i;
  }
  EXPECT_EQ(skipping.all.events, every.all.events);
}

}  // namespace
}  // namespace hazard
