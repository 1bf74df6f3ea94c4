// moos::Lockstep: apps at different AppTicks cycle exactly on their own grids, in the order
// added when due together; mail posted by an earlier app in an instant is seen by a later one in
// the same instant; the clock moves only forward, to due times.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "moos/bus.hpp"
#include "moos/clock.hpp"
#include "moos/lockstep.hpp"

namespace moos {
namespace {

/// Records the MOOS time of each iterate() and the mail it saw; posts TICK_<name> each time.
class Recorder final : public MoosApp {
 public:
  Recorder(std::string name, std::vector<std::string>& log, bool listens = false)
      : MoosApp(AppTraits{name}), log_(log), listens_(listens) {}

 protected:
  bool on_start_up() override {
    if (listens_) register_variable("TICK_A");
    return true;
  }
  void on_new_mail(const std::vector<Message>& mail) override {
    for (const Message& m : mail) log_.push_back(app_name() + " got " + m.key + " @" + std::to_string(m.time));
  }
  void iterate() override {
    log_.push_back(app_name() + " @" + std::to_string(cycle_time()));
    notify("TICK_" + app_name(), cycle_time());
  }

 private:
  std::vector<std::string>& log_;
  bool listens_;
};

AppSettings settings(const std::string& name, double tick_hz) {
  AppSettings s;
  s.app_name = s.moos_name = name;
  s.app_tick_hz = tick_hz;
  return s;
}

TEST(Lockstep, CyclesEachAppOnItsGridInTheOrderAdded) {
  ManualClock clock(0.0);
  InProcessBus bus(clock);
  std::vector<std::string> log;
  Recorder a("A", log), b("B", log, true);
  auto ca = bus.connect("A"), cb = bus.connect("B");
  ASSERT_TRUE(a.start(*ca, settings("A", 2.0)));
  ASSERT_TRUE(b.start(*cb, settings("B", 1.0)));
  Lockstep lockstep(bus, clock);
  lockstep.add(a);
  lockstep.add(b);
  EXPECT_FALSE(lockstep.run_until(1.0));
  // A at 0, 0.5, 1; B at 0 and 1, after A; B sees A's tick of the same instant, and at 1 the
  // ticks of 0.5 and 1 in order.
  const std::vector<std::string> expected = {
      "A @0.000000", "B got TICK_A @0.000000", "B @0.000000", "A @0.500000", "A @1.000000",
      "B got TICK_A @0.500000", "B got TICK_A @1.000000", "B @1.000000"};
  EXPECT_EQ(log, expected);
  EXPECT_DOUBLE_EQ(lockstep.moos_time(), 1.0);
}

TEST(Lockstep, StopEndsTheRunAtTheStepThatAskedAndTheClockStaysThere) {
  ManualClock clock(0.0);
  InProcessBus bus(clock);
  std::vector<std::string> log;
  Recorder a("A", log);
  auto ca = bus.connect("A");
  ASSERT_TRUE(a.start(*ca, settings("A", 4.0)));
  Lockstep lockstep(bus, clock);
  lockstep.add(a);
  int steps = 0;
  EXPECT_TRUE(lockstep.run_until(100.0, [&] { return ++steps == 3; }));
  EXPECT_DOUBLE_EQ(lockstep.moos_time(), 0.5);
  EXPECT_EQ(log.size(), 3u);
}

TEST(Lockstep, WithoutAppsTheClockMovesToTheEnd) {
  ManualClock clock(10.0);
  InProcessBus bus(clock);
  Lockstep lockstep(bus, clock);
  EXPECT_EQ(lockstep.next_due_moos_s(), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(lockstep.run_until(20.0));
  EXPECT_DOUBLE_EQ(lockstep.moos_time(), 20.0);
}

}  // namespace
}  // namespace moos
