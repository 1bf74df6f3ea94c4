// MoosApp's fetch promise (Comms::expect_fetch_within) only where the comms takes it: a BusClient
// ignores promises, so an app on the bus works none out (no clock read per cycle for nothing).
#include <gtest/gtest.h>

#include <vector>

#include "moos/app.hpp"
#include "moos/bus.hpp"

namespace moos {
namespace {

constexpr double kT0 = 1700000000.0;

/// A connected Comms that records the promised fetches, taking promises or not.
class PromiseCounter final : public Comms {
 public:
  explicit PromiseCounter(bool takes_promises) : Comms("pPromise", takes_promises) {}
  bool is_connected() const override { return true; }
  std::uint64_t connection_count() const override { return 1; }
  std::string community() const override { return "alpha"; }
  Clock& clock() const override { return clock_; }
  double time_warp() const override { return 1.0; }
  double skew_s() const override { return 0.0; }
  void fetch_into(std::vector<Message>& mail) override { mail.clear(); }
  void expect_fetch_within(double real_s) override { promises.push_back(real_s); }

  std::vector<double> promises;

 protected:
  bool transmit(Message&&) override { return true; }

 private:
  mutable ManualClock clock_{kT0};
};

std::vector<double> promises_on(PromiseCounter& comms) {
  MoosApp app(AppTraits{"pPromise", 4.0});
  AppSettings settings;
  settings.app_name = settings.moos_name = "pPromise";
  settings.app_tick_hz = 4.0;
  EXPECT_TRUE(app.start(comms, settings));
  app.run_for(1.0);
  return comms.promises;
}

TEST(AppFetchPromise, ACommsThatTakesPromisesGetsOnePerCycle) {
  PromiseCounter comms(true);
  EXPECT_EQ(promises_on(comms).size(), 5u);  // cycles at 0, 0.25, ..., 1
}

TEST(AppFetchPromise, ACommsThatIgnoresPromisesIsNotGivenAny) {
  PromiseCounter comms(false);
  EXPECT_TRUE(promises_on(comms).empty());
}

TEST(AppFetchPromise, ABusClientIgnoresPromises) {
  ManualClock clock(kT0);
  InProcessBus bus(clock);
  EXPECT_FALSE(bus.connect("pA")->takes_fetch_promises());
}

}  // namespace
}  // namespace moos
