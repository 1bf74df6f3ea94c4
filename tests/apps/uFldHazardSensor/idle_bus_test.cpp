// IdleAppTick on the sensor (opt-in; docs/differences.md): the same mission with and without it
// posts the same engine postings at the same times, with far fewer cycles while nothing happens.
#include <gtest/gtest.h>

#include <tuple>

#include "sensor_on_bus.hpp"

namespace ufld_hazard_sensor::testing {
namespace {

struct Observed {
  std::vector<std::tuple<std::string, std::string, double>> postings;  ///< engine postings
  std::uint64_t iterations = 0;
};

/// One run of the app on its own bus (the fixture's members, without a test body of its own).
struct SensorRun : SensorOnBus {
  void TestBody() override {}
  Observed play(const std::string& extra);
};

/// A vehicle configures, surveys a column of objects for 60 s, asks for classifications, and then
/// stays silent for 20 minutes: mail at irregular times, played against `extra` framework lines.
Observed SensorRun::play(const std::string& extra) {
  std::string block = extra + "  sensor_config = width=20, exp=2, pclass=0.7\n  random_seed = 5\n";
  for (int i = 0; i < 20; ++i) {
    block += "  hazard = x=" + std::to_string(i % 2 == 0 ? 6 : -6) + ",y=" + std::to_string(3 * i + 2) +
             ",label=o" + std::to_string(i) + ",type=" + (i % 3 == 0 ? "hazard" : "benign") + "\n";
  }
  start(block);
  run_for(7.3);
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=0.8");
  for (int s = 0; s < 60; ++s) {
    post("UHZ_SENSOR_REQUEST", "vname=alpha");
    post("NODE_REPORT", "NAME=alpha,X=0,Y=" + std::to_string(s) + ",SPD=1,HDG=0");
    run_for(s % 3 == 0 ? 0.6 : 1.3);
  }
  for (int i = 0; i < 20; ++i) post("UHZ_CLASSIFY_REQUEST", "vname=alpha,label=o" + std::to_string(i));
  run_for(1200.0);

  Observed seen;
  for (const auto& m : bus.postings()) {
    if (m.source == "uFldHazardSensor" && !is_framework_posting(m.key))
      seen.postings.emplace_back(m.key, m.sval, m.time);
  }
  seen.iterations = app->iteration();
  return seen;
}

TEST(SensorIdleAppTick, PostsWhatTheSensorPostsWithoutItInFewerCycles) {
  const Observed every = SensorRun().play("");
  const Observed idle = SensorRun().play("  IdleAppTick = 0.1\n");
  EXPECT_EQ(idle.postings, every.postings);
  std::size_t detections = 0, answers = 0;
  for (const auto& p : every.postings) {
    detections += std::get<0>(p) == "UHZ_DETECTION_REPORT";
    answers += std::get<0>(p) == "UHZ_HAZARD_REPORT";
  }
  EXPECT_GT(detections, 2u);  // the scenario exercises sensing and classification
  EXPECT_GT(answers, 2u);
  // Without the option: AppTick 4 for about 1,290 s. With it: every slot while the sensor is on
  // and answers are queued (about 600 s after the last request: 2,400 slots) and then a cycle
  // per options summary (every 10 s).
  EXPECT_GT(every.iterations, 5000u);
  EXPECT_LT(idle.iterations, every.iterations * 3 / 4);
}

}  // namespace
}  // namespace ufld_hazard_sensor::testing
