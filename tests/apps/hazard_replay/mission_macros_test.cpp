// hazard_replay reads a mission file with $(NAME) macros, as a MOOS app does: `--NAME=value`
// arguments give them (missions/jake/jake.moos needs --PORT, --WARP, --SEED and --VIEW_PORT).
#include <gtest/gtest.h>

#include <string>

#include "replay_support.hpp"
#include "text_count.hpp"

namespace hazard_replay {
namespace {

using test_support::count_of;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::mission;
using testing::run;

void make_macro_mission(const ScratchDir& dir) {
  write_file(dir / "m.moos", mission("  AppTick = $(TICK)\n  hazard_file = $(FIELD)\n"
                                     "  sensor_config = width=25, exp=4, pclass=0.8\n"
                                     "  show_hazards = false\n  random_seed = $(SEED)\n"));
  write_file(dir / "field.txt", "hazard = x=0,y=0,label=a,type=hazard\n");
  write_file(dir / "in.alog", alog({{0.0, "UHZ_CONFIG_REQUEST", "vname=v1,width=25,pd=1"},
                                    {0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
                                    {0.5, "NODE_REPORT", "NAME=v1,X=0,Y=0,SPD=1,HDG=0"},
                                    {1.0, "UHZ_SENSOR_REQUEST", "vname=v1"}}));
}

TEST(ReplayMissionMacros, NameValueArgumentsFillTheMissionsMacros) {
  ScratchDir dir;
  make_macro_mission(dir);
  const auto r = run(dir, {"m.moos", "in.alog", "--TICK=2", "--FIELD=field.txt", "--SEED=5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("is not defined"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("seed 5 (random_seed), AppTick 2 Hz"), std::string::npos) << r.err;
  EXPECT_EQ(count_of(r.out, "UHZ_DETECTION_REPORT "), 1u) << r.out;  // the field was loaded
}

TEST(ReplayMissionMacros, AMacroLeftUndefinedIsNamedWithTheArgumentThatDefinesIt) {
  ScratchDir dir;
  make_macro_mission(dir);
  const auto r = run(dir, {"m.moos", "in.alog", "--TICK=2", "--SEED=5"});
  EXPECT_NE(r.err.find("$(FIELD) is not defined (give --FIELD=value)"), std::string::npos)
      << r.err;
  EXPECT_EQ(count_of(r.out, "UHZ_DETECTION_REPORT "), 0u) << r.out;  // no field, no detection
}

}  // namespace
}  // namespace hazard_replay
