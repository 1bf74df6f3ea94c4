// hazard_replay on the hostile examples (the engine's bad input, docs/robustness.md): a 10 km jump
// under swath_sweep over a dense field, a negative speed, a 1e308 width, and a hazard file with a
// byte-order mark and a NUL byte in a label. Each run ends normally with a warning naming the
// value on standard error.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "replay_support.hpp"
#include "text_count.hpp"

namespace hazard_replay {
namespace {

using test_support::count_of;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::Line;
using testing::mission;
using testing::run;

void make_mission(const ScratchDir& dir, const std::string& block, const std::string& hazards,
                  const std::vector<Line>& input) {
  std::filesystem::create_directories(dir / "fields");
  write_file(dir / "m.moos", mission(block));
  write_file(dir / "fields/hazards.txt", hazards);
  write_file(dir / "in.alog", alog(input));
}

TEST(ReplayHardening, ATenKilometreJumpIsNotSweptOverADenseField) {
  ScratchDir dir;
  std::string hazards;
  for (int i = 0; i < 20000; ++i) {  // one object every half metre along the jump
    hazards += "hazard = x=0,y=" + std::to_string(i / 2) + (i % 2 ? ".5" : "") + ",label=o" +
               std::to_string(i) + ",type=hazard\n";
  }
  make_mission(dir,
               "  AppTick = 4\n  hazard_file = fields/hazards.txt\n"
               "  sensor_config = width=25, exp=4, pclass=0.8\n  show_hazards = false\n"
               "  swath_sweep = true\n  max_vehicle_speed = off\n",
               hazards,
               {{0.0, "UHZ_CONFIG_REQUEST", "vname=v1,width=25,pd=1"},
                {0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
                {0.5, "NODE_REPORT", "NAME=v1,X=100,Y=-50,SPD=1,HDG=0"},
                {1.0, "NODE_REPORT", "NAME=v1,X=0,Y=9990,SPD=1,HDG=0"},
                {2.0, "UHZ_SENSOR_REQUEST", "vname=v1"}});
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("jumped"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("kMaxSweepJump_m"), std::string::npos);
  // Only the arrival's swath (10 m long: about 21 objects at pd 1), not 20,000.
  const std::size_t detections = count_of(r.out, "UHZ_DETECTION_REPORT ");
  EXPECT_GT(detections, 0u);
  EXPECT_LE(detections, 25u);
}

TEST(ReplayHardening, NegativeSpeedAndHugeWidthAreRefusedNamingTheValue) {
  ScratchDir dir;
  make_mission(dir,
               "  AppTick = 4\n  hazard_file = fields/hazards.txt\n"
               "  sensor_config = width=1e308, exp=4, pclass=0.8\n"
               "  sensor_config = width=25, exp=4, pclass=0.8\n  show_hazards = false\n",
               "hazard = x=0,y=0,label=a,type=hazard\n",
               {{0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
                {0.5, "NODE_REPORT", "NAME=v1,X=0,Y=0,SPD=-3,HDG=0"},
                {1.0, "UHZ_CONFIG_REQUEST", "vname=v1,width=1e308,pd=0.5"}});
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("field 'width' value '1e308' is above 1000000 m"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("field 'SPD' value '-3' is outside [0, 1000] m/s"), std::string::npos);
  EXPECT_EQ(r.out.find("width=1000000000"), std::string::npos);  // never posted
}

TEST(ReplayHardening, AByteOrderMarkLoadsAndANulInALabelIsRefusedNamingFileAndLine) {
  ScratchDir dir;
  const std::string hazards = "\xEF\xBB\xBFhazard = x=0,y=0,label=a,type=hazard\n"
                              "hazard = x=1,y=0,label=b" + std::string(1, '\0') +
                              "c,type=hazard\n";
  make_mission(dir,
               "  AppTick = 4\n  hazard_file = fields/hazards.txt\n"
               "  sensor_config = width=25, exp=4, pclass=0.8\n  show_hazards = false\n",
               hazards, {{0.0, "UHZ_SENSOR_REQUEST", "vname=v1"}});
  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("fields/hazards.txt:2: field 'label' value 'b\\x00c' contains a control "
                       "byte"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("hazards.txt:1:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\0'), std::string::npos);
}

}  // namespace
}  // namespace hazard_replay
