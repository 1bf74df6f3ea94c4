// After each cycle an app tells its comms when it will fetch again (Comms::expect_fetch_within,
// MoosApp::promise_next_fetch), so a TcpClient can leave reading to it; while it skips slots
// (IdleAppTick) it promises nothing, so mail still wakes it.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "moos/app.hpp"

namespace moos {
namespace {

constexpr double kT0 = 1700000000.0;
constexpr double kAppTickHz = 4.0;
constexpr double kWarp = 2.0;

/// A connected Comms that takes every posting and records the promised fetches.
class PromiseRecorder final : public Comms {
 public:
  PromiseRecorder() : Comms("pPromise") {}
  bool is_connected() const override { return true; }
  std::uint64_t connection_count() const override { return 1; }
  std::string community() const override { return "alpha"; }
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return kWarp; }
  double skew_s() const override { return 0.0; }
  std::vector<Message> fetch() override { return {}; }
  void expect_fetch_within(double real_s) override { promises.push_back(real_s); }

  std::vector<double> promises;

 protected:
  bool transmit(Message) override { return true; }

 private:
  mutable ManualClock clock_{kT0};
};

class QuietApp : public MoosApp {
 public:
  QuietApp() : MoosApp(AppTraits{"pPromise", kAppTickHz}) {}
  double quiet_until = std::numeric_limits<double>::infinity();  ///< absolute MOOS s

 protected:
  void iterate() override {}
  double quiet_until_moos_s(double now_moos_s) const override {
    return std::max(now_moos_s, quiet_until);
  }
};

AppSettings settings(std::optional<double> idle_app_tick_hz) {
  AppSettings s;
  s.app_name = s.moos_name = "pPromise";
  s.community = "alpha";
  s.app_tick_hz = kAppTickHz;
  s.time_warp = kWarp;
  s.idle_app_tick_hz = idle_app_tick_hz;
  return s;
}

TEST(AppFetchPromise, EveryCyclePromisesTheNextSlotInRealSeconds_Issue14) {
  PromiseRecorder comms;
  QuietApp app;
  ASSERT_TRUE(app.start(comms, settings(std::nullopt)));
  app.run_for(5.0);
  ASSERT_EQ(comms.promises.size(), 21u);  // one per cycle: 0, 0.25, ..., 5
  for (double p : comms.promises) EXPECT_NEAR(p, 1.0 / kAppTickHz / kWarp, 1e-9);
}

TEST(AppFetchPromise, AnAppThatSkipsSlotsPromisesNothing_Issue14) {
  PromiseRecorder comms;
  QuietApp app;
  ASSERT_TRUE(app.start(comms, settings(0.5)));  // quiet for ever: cycles every 2 MOOS s
  app.run_for(5.0);
  ASSERT_EQ(comms.promises.size(), 3u);  // 0, 2, 4
  for (double p : comms.promises) EXPECT_EQ(p, 0.0);
}

TEST(AppFetchPromise, AnIdleTickAppThatIsNeverQuietStillPromises_Issue14) {
  PromiseRecorder comms;
  QuietApp app;
  app.quiet_until = 0.0;  // quiet_until_moos_s returns now: never quiet
  ASSERT_TRUE(app.start(comms, settings(0.5)));
  app.run_for(1.0);
  ASSERT_EQ(comms.promises.size(), 5u);
  for (double p : comms.promises) EXPECT_NEAR(p, 1.0 / kAppTickHz / kWarp, 1e-9);
}

}  // namespace
}  // namespace moos
