// Bounds on what outside input can make grow (engine.hpp kMaxVehicles,
// kMaxClassifyQueue, kMaxCreditsPerObject): each is reached here, and reaching it gives a run
// warning naming it and a counted drop, never growth.
#include <gtest/gtest.h>

#include <string>

#include "hazard/report.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::credits_of;
using testing::Driver;
using testing::quiet_block;

std::string numbered(const char* prefix, std::size_t i) {
  std::string digits = std::to_string(i);
  return prefix + std::string(5 - digits.size(), '0') + digits;
}

void fill_vehicle_table(Driver& d) {
  for (std::size_t i = 0; i < kMaxVehicles; ++i) d.pose(numbered("v", i), 0, 0);
  ASSERT_EQ(d.engine.vehicles_by_name().size(), kMaxVehicles);
}

TEST(EngineBounds, FullVehicleTableDropsNewVehiclesWithOneWarning) {
  Driver d(quiet_block());
  fill_vehicle_table(d);
  const Outputs first = d.pose("newcomer", 0, 0);
  EXPECT_TRUE(contains(first.run_warnings, "kMaxVehicles = 1000"));
  EXPECT_TRUE(contains(first.run_warnings, "newcomer"));
  EXPECT_TRUE(d.mail("UHZ_SENSOR_REQUEST", "vname=second").run_warnings.empty());
  EXPECT_TRUE(d.mail("UHZ_CONFIG_REQUEST", "vname=third,pd=0.5").run_warnings.empty());
  EXPECT_EQ(d.engine.drops().vehicles, 3u);
  EXPECT_FALSE(d.engine.find_vehicle("newcomer"));
  EXPECT_EQ(d.engine.vehicles_by_name().size(), kMaxVehicles);
  d.tick();
  EXPECT_NE(format_report(collect_report_data(d.engine)).find("Drops: vehicles refused 3"),
            std::string::npos);
}

TEST(EngineBounds, FullVehicleTableForgetsTheVehicleSilentLongest) {
  Driver d(quiet_block());
  fill_vehicle_table(d);
  // Every vehicle but v00007 reports again later: v00007 is the one silent longest.
  d.now = 10;
  for (std::size_t i = 0; i < kMaxVehicles; ++i) {
    if (i != 7) d.pose(numbered("v", i), 0, 0);
  }
  d.now = kForgetSilentAfter_s - 1;  // silent 3599 s: not yet
  EXPECT_TRUE(contains(d.pose("late", 0, 0).run_warnings, "none silent for 3600 s"));
  d.now = kForgetSilentAfter_s;
  const Outputs out = d.pose("newcomer", 0, 0);
  EXPECT_TRUE(contains(out.run_warnings, "forgot v00007, silent for 3600 s"));
  EXPECT_FALSE(d.engine.find_vehicle("v00007"));
  ASSERT_TRUE(d.engine.find_vehicle("newcomer"));
  EXPECT_TRUE(d.vehicle("newcomer").pose.has_value());
  EXPECT_EQ(d.engine.drops().vehicles_forgotten, 1u);
  EXPECT_EQ(d.engine.vehicles_by_name().size(), kMaxVehicles);
  d.tick();  // the invariants (name order) hold after the slot was reused
}

// One pass at pd 1 over `count` hazards packed near the origin grants one credit each.
std::string packed_hazards(std::size_t count) {
  std::string block;
  for (std::size_t i = 0; i < count; ++i) {
    block += "hazard = x=" + std::to_string(static_cast<double>(i % 100) * 0.01) +
             ",y=" + std::to_string(static_cast<double>(i / 100) * 0.01) +
             ",label=" + numbered("h", i) + ",type=hazard\n";
  }
  return block;
}

TEST(EngineBounds, FullClassifyQueueRefusesTheRequestAndKeepsItsCredit) {
  Driver d(quiet_block("min_classify_interval = 1000\n" + packed_hazards(kMaxClassifyQueue + 1)));
  d.sense_at_origin("v", "25", "1");
  for (std::size_t i = 0; i < kMaxClassifyQueue; ++i) {
    d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + numbered("h", i));
  }
  EXPECT_EQ(d.vehicle("v").queue.size(), kMaxClassifyQueue);
  const std::string last = numbered("h", kMaxClassifyQueue);
  const Outputs refused = d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + last);
  EXPECT_TRUE(contains(refused.run_warnings, "kMaxClassifyQueue = 10000"));
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + last).run_warnings.empty());
  EXPECT_EQ(d.engine.drops().classify_requests, 2u);
  EXPECT_EQ(d.vehicle("v").queue.size(), kMaxClassifyQueue);
  const ObjectId id = *d.engine.field().find(last);
  EXPECT_EQ(credits_of(d.vehicle("v"), id).size(), 1u);  // the refused request kept its credit
  d.tick_at(1);  // one answer released: room for one
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + last).run_warnings.empty());
  EXPECT_EQ(d.vehicle("v").queue.size(), kMaxClassifyQueue);
}

TEST(EngineBounds, CreditsPerObjectStopAtTheBound) {
  Driver d(quiet_block("hazard = x=0,y=0,label=A,type=hazard\n"));
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1");
  d.sensor_on("v");
  Outputs warnings;
  for (std::size_t pass = 0; pass < kMaxCreditsPerObject + 2; ++pass) {
    d.pose("v", 0, 0);
    testing::append(warnings, d.tick_at(d.now + 1));
    d.pose("v", 0, 500);
    d.tick_at(d.now + 1);
  }
  const ObjectId id = *d.engine.field().find("A");
  EXPECT_EQ(d.vehicle("v").counters.detections, static_cast<int>(kMaxCreditsPerObject + 2));
  EXPECT_EQ(credits_of(d.vehicle("v"), id).size(), kMaxCreditsPerObject);
  EXPECT_EQ(d.engine.drops().credits, 2u);
  EXPECT_TRUE(contains(warnings.run_warnings, "kMaxCreditsPerObject"));
  EXPECT_EQ(credits_of(d.vehicle("v"), id).front().pass, 1u);  // the oldest are kept
}

}  // namespace
}  // namespace hazard
