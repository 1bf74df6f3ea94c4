// hazard::Driver (driver.hpp): the time clamp, the dispatch on variable names, unknown variables.
#include <gtest/gtest.h>

#include "hazard/driver.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::quiet_block;
using testing::setup_from;
using testing::values_of;

hazard::Driver make_driver(const std::string& extra = {}) {
  return hazard::Driver(setup_from(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n" + extra)),
                        SeedChoice{1, SeedSource::kCommandLine});
}

TEST(Driver, MailFromTheFutureIsTakenAtTheCallersTime) {
  hazard::Driver d = make_driver();
  d.start(100.0);
  const TimedOutputs out = d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 250.0}, 120.0);
  EXPECT_EQ(out.time_s, 120.0);
  EXPECT_EQ(*d.engine().vehicle(*d.engine().find_vehicle("v")).last_sensor_request_s, 120.0);
  EXPECT_EQ(d.last_time_s(), 120.0);
}

TEST(Driver, MailFromThePastIsTakenAtTheLastTimeGiven) {
  hazard::Driver d = make_driver();
  d.start(100.0);
  d.step(130.0);
  const TimedOutputs out = d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 90.0}, 140.0);
  EXPECT_EQ(out.time_s, 130.0);  // never before the last iteration
  EXPECT_EQ(*d.engine().vehicle(0).last_sensor_request_s, 130.0);
  // Without a caller's time, the mail's own time is used (hazard_replay, tests).
  EXPECT_EQ(d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 135.5}).time_s, 135.5);
}

TEST(Driver, AnIterationNeverRunsBeforeTheLastMail) {
  hazard::Driver d = make_driver();
  d.start(0.0);
  d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 10.0});
  const TimedOutputs out = d.step(5.0);
  EXPECT_EQ(out.time_s, 10.0);
  EXPECT_EQ(values_of(out.outputs, "UHZ_OPTIONS_SUMMARY").size(), 1u);
  EXPECT_EQ(d.step(11.0).time_s, 11.0);
}

TEST(Driver, DeliveryIntoAnOutputsAppendsAndReturnsTheTime) {
  hazard::Driver d = make_driver();
  d.start(100.0);
  Outputs out;
  out.events.push_back("kept");
  EXPECT_EQ(d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 250.0}, 120.0, out), 120.0);
  EXPECT_EQ(d.deliver(Mail{"NODE_REPORT", "garbage", 90.0}, 130.0, out), 120.0);
  EXPECT_EQ(out.events, std::vector<std::string>{"kept"});
  ASSERT_EQ(out.run_warnings.size(), 1u);  // appended, nothing replaced
  EXPECT_NE(out.run_warnings[0].find("NODE_REPORT"), std::string::npos);
}

// Mail in turn from three vehicles (the last two names found are checked before hashing):
// every report reaches its own vehicle.
TEST(Driver, MailFromVehiclesInTurnReachesEach) {
  hazard::Driver d = make_driver();
  d.start(0.0);
  const std::vector<std::string> names = {"alpha", "b", "charlie_the_long_named_vehicle"};
  for (int round = 0; round < 3; ++round) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const double x = 10.0 * static_cast<double>(i) + round;
      d.deliver(Mail{"NODE_REPORT", testing::node_report(names[i], x, 0), 1.0 + round});
    }
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto id = d.engine().find_vehicle(names[i]);
    ASSERT_TRUE(id) << names[i];
    EXPECT_EQ(d.engine().vehicle(*id).pose->position_m.x, 10.0 * static_cast<double>(i) + 2)
        << names[i];
  }
}

TEST(Driver, StartRecordsTheStartTime) {
  hazard::Driver d = make_driver();
  EXPECT_FALSE(d.last_time_s());
  EXPECT_EQ(d.start(42.0).time_s, 42.0);
  EXPECT_EQ(d.engine().start_time_s(), 42.0);
}

TEST(Driver, EachSubscriptionReachesItsHandler) {
  hazard::Driver d = make_driver("show_hazards = true\n");
  d.start(0.0);
  d.deliver(Mail{"NODE_REPORT", testing::node_report("v", 0, 0), 1.0});
  const auto& v = [&]() -> const VehicleState& { return d.engine().vehicle(0); };
  ASSERT_TRUE(v().pose);
  d.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 2.0});
  EXPECT_EQ(v().last_sensor_request_s, 2.0);
  const Outputs ack = d.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1", 3.0}).outputs;
  EXPECT_EQ(values_of(ack, "UHZ_CONFIG_ACK_V").size(), 1u);
  const Outputs sensed = d.step(4.0).outputs;
  ASSERT_EQ(values_of(sensed, "UHZ_DETECTION_REPORT").size(), 1u);  // pd 1: object a
  d.deliver(Mail{"UHZ_CLASSIFY_REQUEST", "vname=v,label=a", 5.0});
  EXPECT_EQ(v().queue.size(), 1u);
  d.deliver(Mail{"UHZ_SENSOR_CLEAR", "vname=v", 6.0});
  EXPECT_TRUE(v().queue.empty());
  const Outputs markers = d.deliver(Mail{"PMV_CONNECT", "pMarineViewer", 7.0}).outputs;
  EXPECT_EQ(values_of(markers, "VIEW_MARKER").size(), 1u);
}

TEST(Driver, UnknownVariablesAreIgnoredAndNamesAreCaseSensitive) {
  hazard::Driver d = make_driver();
  d.start(0.0);
  for (const char* variable : {"node_report", "UHZ_SENSOR_REQUEST_V", "DB_TIME", ""}) {
    const TimedOutputs out = d.deliver(Mail{variable, "NAME=v,X=0,Y=0,SPD=1,HDG=0", 1.0});
    EXPECT_TRUE(out.outputs.empty()) << variable;
  }
  EXPECT_TRUE(d.engine().vehicles_by_name().empty());
  // An ignored piece of mail still moves the clock: its time is the engine's time.
  EXPECT_EQ(d.last_time_s(), 1.0);
}

TEST(Driver, AValueBeyondTheBoundIsOneWarning) {
  hazard::Driver d = make_driver();
  const std::string huge(kMaxMailValueBytes + 1, 'x');
  const Outputs out = d.deliver(Mail{"UHZ_SENSOR_REQUEST", huge, 0.0}).outputs;
  ASSERT_EQ(out.run_warnings.size(), 1u);
  EXPECT_NE(out.run_warnings[0].find("bytes exceeds 65536; ignored"), std::string::npos);
  EXPECT_TRUE(out.postings.empty());
}

}  // namespace
}  // namespace hazard
