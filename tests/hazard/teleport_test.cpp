// Teleports under swath_sweep and swath_substeps (engine.hpp kMaxSweepJump_m,
// sensing_track.hpp "Teleports").
#include <gtest/gtest.h>

#include <string>

#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::quiet_block;

// Hostile input: a vehicle that jumps 10 km between two reports does not sweep the jump (a dense
// line of objects lies under it); the arrival is sensed like a start pose, and the jump is
// one run warning and one counted drop.
TEST(SensingTrackEngine, ATeleportIsNotSweptOnlyItsArrivalIsSensed) {
  // A legal 1000 m move afterwards: swept (10 objects more) or sampled at 250 m (2 more).
  const std::pair<std::string, int> modes[] = {{"swath_sweep = true\n", 11},
                                               {"swath_substeps = 4\n", 3}};
  for (const auto& [mode, after_legal_move] : modes) {
    std::string objects;
    for (int i = 1; i < 100; ++i) {
      objects += "hazard = x=0,y=" + std::to_string(i * 100) + ",label=under" +
                 std::to_string(i) + ",type=hazard\n";
    }
    Driver d(quiet_block(mode + objects + "hazard = x=0,y=10000,label=arrival,type=hazard\n"));
    d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1");
    d.sensor_on("v");
    d.pose("v", 0, -20);
    d.tick_at(1);
    d.now = 2;
    const Outputs jump = d.pose("v", 0, 10000);
    EXPECT_TRUE(contains(jump.run_warnings, "jumped 10020.0 m")) << mode;
    EXPECT_TRUE(contains(jump.run_warnings, "kMaxSweepJump_m = 1000 m")) << mode;
    d.tick_at(3);
    EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 1) << mode;
    EXPECT_TRUE(contains(d.all.events, "(label arrival)")) << mode;
    EXPECT_EQ(d.engine.drops().teleports, 1u) << mode;
    // A move of exactly the bound is not a teleport.
    d.now = 4;
    EXPECT_TRUE(d.pose("v", 0, 9000).run_warnings.empty()) << mode;
    d.tick_at(5);
    EXPECT_EQ(d.vehicle("v").counters.hazard_chances, after_legal_move) << mode;
  }
}

}  // namespace
}  // namespace hazard
