// IdleAppTick (ours, opt-in; include/moos/app.hpp, src/moos/app_idle.cpp): a quiet app skips
// AppTick slots, mail ends the skipping at the slot it would have had, every cycle stays on the
// AppTick grid, and without the option every slot is a cycle. After each cycle an app tells its
// comms when it will fetch again (Comms::expect_fetch_within), so a TcpClient can leave reading
// to it; while it skips slots it promises nothing, so mail still wakes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "moos/app.hpp"
#include "moos/bus.hpp"

namespace moos {
namespace {

constexpr double kT0 = 1700000000.0;
constexpr double kAppTickHz = 4.0;

/// An app whose quiet time the test sets, recording the MOOS time of every iteration and the
/// cycle at which each piece of mail was handled.
class QuietApp : public MoosApp {
 public:
  QuietApp() : MoosApp(AppTraits{"pQuiet", kAppTickHz}) {}

  double quiet_until = std::numeric_limits<double>::infinity();  ///< absolute MOOS s
  std::vector<double> iteration_times;
  std::vector<double> mail_times;

 protected:
  bool on_start_up() override {
    register_variable("IN");
    return true;
  }
  void on_new_mail(const std::vector<Message>& mail) override {
    for (std::size_t i = 0; i < mail.size(); ++i) mail_times.push_back(cycle_time());
  }
  void iterate() override { iteration_times.push_back(cycle_time()); }
  double quiet_until_moos_s(double now_moos_s) const override {
    return std::max(now_moos_s, quiet_until);
  }
};

/// QuietApp's settings at AppTick kAppTickHz, with IdleAppTick `idle_app_tick_hz`.
AppSettings quiet_settings(std::optional<double> idle_app_tick_hz) {
  AppSettings s;
  s.app_name = s.moos_name = "pQuiet";
  s.community = "alpha";
  s.app_tick_hz = kAppTickHz;
  s.idle_app_tick_hz = idle_app_tick_hz;
  return s;
}

class IdleApp : public ::testing::Test {
 protected:
  void start(std::optional<double> idle_app_tick_hz) {
    AppSettings s = quiet_settings(idle_app_tick_hz);
    s.time_warp = bus.time_warp();
    app_comms = bus.connect(s.moos_name);
    ASSERT_TRUE(app.start(*app_comms, s));
  }
  /// True when `t` lies on the AppTick grid that starts at kT0.
  static bool on_grid(double t) {
    const double periods = (t - kT0) * kAppTickHz;
    return std::fabs(periods - std::round(periods)) < 1e-6;
  }

  ManualClock clock{kT0};
  InProcessBus bus{clock, InProcessBus::Options{"alpha", 1.0}};
  std::unique_ptr<BusClient> tester = bus.connect("tester");
  std::unique_ptr<BusClient> app_comms;
  QuietApp app;
};

TEST_F(IdleApp, WithoutTheOptionEverySlotIsACycle) {
  start(std::nullopt);
  app.run_for(20.0);
  EXPECT_EQ(app.iteration_times.size(), 81u);  // 0, 0.25, ..., 20
}

TEST_F(IdleApp, AQuietAppCyclesAtTheIdleRateOnTheAppTickGrid) {
  start(0.5);
  app.run_for(20.0);
  ASSERT_EQ(app.iteration_times.size(), 11u);  // 0, 2, ..., 20
  for (std::size_t i = 0; i < app.iteration_times.size(); ++i) {
    EXPECT_NEAR(app.iteration_times[i] - kT0, 2.0 * static_cast<double>(i), 1e-6) << i;
  }
  // The framework's own postings see the gap: _ITER_GAP is 8 AppTick periods.
  const auto gaps = bus.postings_of("PQUIET_ITER_GAP");
  ASSERT_FALSE(gaps.empty());
  EXPECT_NEAR(gaps.back().dval, 8.0, 1e-6);
}

TEST_F(IdleApp, AnAppThatIsNeverQuietCyclesEverySlot) {
  app.quiet_until = 0.0;  // quiet_until_moos_s returns now: never quiet
  start(0.5);
  app.run_for(20.0);
  EXPECT_EQ(app.iteration_times.size(), 81u);
}

TEST_F(IdleApp, TheQuietTimeEndsTheSkippingBeforeTheIdleTickDoes) {
  app.quiet_until = kT0 + 1.1;
  start(0.1);  // alone, the idle tick would wait 10 s
  app.run_for(2.0);
  ASSERT_GE(app.iteration_times.size(), 2u);
  EXPECT_NEAR(app.iteration_times[1] - kT0, 1.25, 1e-6);  // the first slot at or after 1.1
  EXPECT_TRUE(on_grid(app.iteration_times[1]));
}

TEST_F(IdleApp, MailIsHandledAtTheSlotItWouldHaveHadWithoutTheOption) {
  start(0.1);
  app.run_for(3.3);  // cycles at 0 only; the clock now reads 3.3
  ASSERT_EQ(app.iteration_times.size(), 1u);
  ASSERT_TRUE(tester->notify("IN", 1.0));
  app.run_for(1.0);
  ASSERT_EQ(app.mail_times.size(), 1u);
  EXPECT_NEAR(app.mail_times[0] - kT0, 3.5, 1e-6);  // the next slot of the grid
  ASSERT_EQ(app.iteration_times.size(), 2u);        // then quiet again until 13.5
  EXPECT_NEAR(app.iteration_times[1] - kT0, 3.5, 1e-6);
}

TEST_F(IdleApp, EveryCycleFallsOnTheGridUnderIrregularMail) {
  start(0.3);
  for (double gap : {0.07, 1.9, 0.4, 5.3, 0.01, 2.22, 7.7}) {
    app.run_for(gap);
    ASSERT_TRUE(tester->notify("IN", gap));
  }
  app.run_for(1.0);
  EXPECT_EQ(app.mail_times.size(), 7u);
  for (double t : app.iteration_times) EXPECT_TRUE(on_grid(t)) << t - kT0;
}

/// A clock whose sleeps end late (as a loaded machine's do) and that stops the loop at a time.
class LateClock final : public Clock {
 public:
  LateClock(double late_real_s, double stop_at_unix_s, std::atomic<bool>& stop)
      : late_real_s_(late_real_s), stop_at_unix_s_(stop_at_unix_s), stop_(stop) {}
  double unix_now_s() const override { return inner_.unix_now_s(); }
  void sleep_real_s(double real_s) override {
    inner_.advance_real_s(std::max(real_s, 0.0) + late_real_s_);
    if (inner_.unix_now_s() >= stop_at_unix_s_) stop_ = true;
  }

 private:
  ManualClock inner_{kT0};
  double late_real_s_;
  double stop_at_unix_s_;
  std::atomic<bool>& stop_;
};

// The real loop re-reads the clock after every sleep; mail must still be handled at its slot
// when every sleep ends late (it once chased the next slot for ever).
TEST(IdleAppLoop, MailIsHandledWhenEverySleepEndsLate) {
  std::atomic<bool> stop{false};
  LateClock clock(0.01, kT0 + 30.0, stop);
  InProcessBus bus{clock, InProcessBus::Options{"alpha", 1.0}};
  auto tester = bus.connect("tester");
  auto comms = bus.connect("pQuiet");
  QuietApp app;
  ASSERT_TRUE(app.start(*comms, quiet_settings(0.05)));  // alone, a cycle every 20 s
  app.cycle();
  clock.sleep_real_s(3.0);
  ASSERT_TRUE(tester->notify("IN", 1.0));  // at about 3.01 s
  app.run_until_stopped(&stop);
  ASSERT_EQ(app.mail_times.size(), 1u);
  EXPECT_LT(app.mail_times[0] - kT0, 3.25 + 0.02);  // the slot at 3.25, give or take a late sleep
}

TEST(IdleAppTickSetting, IsOptInAndCheckedLikeAppTick) {
  auto resolve = [](const std::string& block) {
    std::vector<MissionError> errors;
    const MissionFile m = MissionFile::parse("ProcessConfig = pQuiet\n{\n" + block + "}\n", "m.moos", {}, &errors);
    return resolve_app_settings(AppTraits{"pQuiet", 4.0}, parse_command_line({"pQuiet", "m.moos"}), &m);
  };
  EXPECT_FALSE(resolve(" AppTick = 4\n").idle_app_tick_hz);
  const AppSettings set = resolve(" IdleAppTick = 0.2\n");
  ASSERT_TRUE(set.idle_app_tick_hz);
  EXPECT_EQ(*set.idle_app_tick_hz, 0.2);
  EXPECT_TRUE(set.config_lines.empty());  // a framework key, not the app's
  for (const char* bad : {"0", "-1", "1e300", "slow"}) {
    const AppSettings s = resolve(std::string(" IdleAppTick = ") + bad + "\n");
    EXPECT_FALSE(s.idle_app_tick_hz) << bad;
    const std::string expected = std::string("Invalid IdleAppTick: ") + bad +
                                 " (must be a number in [0.001, 1000] Hz) (m.moos:3)";
    EXPECT_EQ(std::count(s.config_warnings.begin(), s.config_warnings.end(), expected), 1) << bad;
  }
}

TEST(SystemClockSleep, MailEndsASleepUnlessWokenEarly) {
  MailSignal wake;
  std::thread poster([&wake] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    wake.notify();
  });
  const auto before = std::chrono::steady_clock::now();
  system_clock().sleep_real_s_unless_woken(30.0, wake);
  const double slept_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
  poster.join();
  EXPECT_LT(slept_s, 15.0);  // woken by the mail, not by the 30-s deadline
  EXPECT_TRUE(wake.pending());
}

/// A connected Comms at warp 2 that takes every posting and records the promised fetches, taking
/// promises (as a TCP client does) or not (as a bus client does).
class PromiseRecorder final : public Comms {
 public:
  static constexpr double kWarp = 2.0;
  explicit PromiseRecorder(bool takes_promises = true) : Comms("pQuiet", takes_promises) {}
  bool is_connected() const override { return true; }
  std::uint64_t connection_count() const override { return 1; }
  std::string community() const override { return "alpha"; }
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return kWarp; }
  double skew_s() const override { return 0.0; }
  void fetch_into(std::vector<Message>& mail) override { mail.clear(); }
  void expect_fetch_within(double real_s) override { promises.push_back(real_s); }

  std::vector<double> promises;

 protected:
  bool transmit(Message&&) override { return true; }

 private:
  mutable ManualClock clock_{kT0};
};

/// Runs `app` on a PromiseRecorder for `moos_s` and returns the promises it made.
std::vector<double> promises_of(QuietApp& app, std::optional<double> idle_app_tick_hz,
                                double moos_s, bool takes_promises = true) {
  PromiseRecorder comms(takes_promises);
  AppSettings s = quiet_settings(idle_app_tick_hz);
  s.time_warp = PromiseRecorder::kWarp;
  EXPECT_TRUE(app.start(comms, s));
  app.run_for(moos_s);
  return comms.promises;
}

constexpr double kPeriod_real_s = 1.0 / kAppTickHz / PromiseRecorder::kWarp;

TEST(AppFetchPromise, EveryCyclePromisesTheNextSlotInRealSeconds) {
  QuietApp app;
  const auto promises = promises_of(app, std::nullopt, 5.0);
  ASSERT_EQ(promises.size(), 21u);  // one per cycle: 0, 0.25, ..., 5
  for (double p : promises) EXPECT_NEAR(p, kPeriod_real_s, 1e-9);
}

// A bus client ignores promises, so an app on the bus works none out (no clock read per cycle).
TEST(AppFetchPromise, ACommsThatIgnoresPromisesIsNotGivenAny) {
  QuietApp app;
  EXPECT_TRUE(promises_of(app, std::nullopt, 5.0, /*takes_promises=*/false).empty());
}

TEST(AppFetchPromise, ABusClientIgnoresPromises) {
  ManualClock clock(kT0);
  InProcessBus bus(clock);
  EXPECT_FALSE(bus.connect("pA")->takes_fetch_promises());
}

TEST(AppFetchPromise, AnAppThatSkipsSlotsPromisesNothing) {
  QuietApp app;  // quiet for ever: cycles every 2 MOOS s
  const auto promises = promises_of(app, 0.5, 5.0);
  ASSERT_EQ(promises.size(), 3u);  // 0, 2, 4
  for (double p : promises) EXPECT_EQ(p, 0.0);
}

TEST(AppFetchPromise, AnIdleTickAppThatIsNeverQuietStillPromises) {
  QuietApp app;
  app.quiet_until = 0.0;  // quiet_until_moos_s returns now: never quiet
  const auto promises = promises_of(app, 0.5, 1.0);
  ASSERT_EQ(promises.size(), 5u);
  for (double p : promises) EXPECT_NEAR(p, kPeriod_real_s, 1e-9);
}

}  // namespace
}  // namespace moos
