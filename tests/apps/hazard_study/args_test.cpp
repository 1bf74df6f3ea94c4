// hazard_study's command line, called directly: settings and assignments, and every refused
// value an error naming the argument (hostile input is bounded in the message).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "study_args.hpp"

namespace hazard_study {
namespace {

std::string error_of(std::vector<std::string> args) {
  args.insert(args.begin(), "m.moos");
  const ParsedArgs p = parse_args(args);
  EXPECT_FALSE(p.options);
  return p.error;
}

TEST(StudyArgs, SetsFormOneSettingLabelledByThemWithoutSetting) {
  const ParsedArgs p = parse_args({"m.moos", "--set=pHazardMgr_archie.swath_width = 30",
                                   "--set", "uFldHazardSensor.sensor_config=width=25, exp=4"});
  ASSERT_TRUE(p.options) << p.error;
  ASSERT_EQ(p.options->settings.size(), 1u);
  const Setting& s = p.options->settings[0];
  EXPECT_EQ(s.label, "pHazardMgr_archie.swath_width=30 uFldHazardSensor.sensor_config=width=25, exp=4");
  ASSERT_EQ(s.assignments.size(), 2u);
  EXPECT_EQ(s.assignments[1].block, "uFldHazardSensor");
  EXPECT_EQ(s.assignments[1].name, "sensor_config");
  EXPECT_EQ(s.assignments[1].value, "width=25, exp=4");
}

TEST(StudyArgs, SettingStartsANewSettingAndTheMissionAloneIsOne) {
  ParsedArgs p = parse_args({"m.moos", "--setting=base", "--setting", "narrow",
                             "--set=a.b=1", "--set=a.b=2", "--seeds=3..7"});
  ASSERT_TRUE(p.options) << p.error;
  ASSERT_EQ(p.options->settings.size(), 2u);
  EXPECT_EQ(p.options->settings[0].label, "base");
  EXPECT_TRUE(p.options->settings[0].assignments.empty());
  EXPECT_EQ(p.options->settings[1].assignments.size(), 2u);
  EXPECT_EQ(p.options->first_seed, 3u);
  EXPECT_EQ(p.options->last_seed, 7u);
  p = parse_args({"m.moos"});
  ASSERT_TRUE(p.options);
  EXPECT_EQ(p.options->settings[0].label, "mission");
}

TEST(StudyArgs, BlockIsEverythingBeforeTheLastDot) {
  const auto a = parse_assignment("my.block.param=x=1");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->block, "my.block");
  EXPECT_EQ(a->name, "param");
  EXPECT_EQ(a->value, "x=1");
}

TEST(StudyArgs, BadValuesAreErrorsNamingTheArgument) {
  EXPECT_EQ(error_of({"--seeds=9..2"}).rfind("--seeds needs A..B", 0), 0u);
  EXPECT_EQ(error_of({"--seeds=0..99999999"}).rfind("--seeds needs A..B", 0), 0u);
  EXPECT_EQ(error_of({"--seeds=x"}).rfind("--seeds needs A..B", 0), 0u);
  EXPECT_EQ(error_of({"--seed=-1"}), "--seed needs a whole number in [0, 2^64): '--seed=-1'");
  EXPECT_EQ(error_of({"--seed=1", "--seeds=1..2"}), "--seed and --seeds exclude each other");
  for (const char* t : {"--max-time=0", "--max-time=-5", "--max-time=nan", "--max-time=1e9",
                        "--max-time=inf"})
    EXPECT_EQ(error_of({t}), std::string("--max-time needs a number of seconds in (0, 3.2e7]: '") +
                                 t + "'");
  EXPECT_EQ(error_of({"--deploy-at=-1"}).rfind("--deploy-at needs", 0), 0u);
  EXPECT_EQ(error_of({"--set=nodot=1"}).rfind("--set needs BLOCK.NAME=VALUE", 0), 0u);
  EXPECT_EQ(error_of({"--set=a.b"}).rfind("--set needs BLOCK.NAME=VALUE", 0), 0u);
  EXPECT_EQ(error_of({"--set=.b=1"}).rfind("--set needs BLOCK.NAME=VALUE", 0), 0u);
  EXPECT_EQ(error_of({"--set=a.=1"}).rfind("--set needs BLOCK.NAME=VALUE", 0), 0u);
  EXPECT_EQ(error_of({"--set=a.b=1\nc"}).rfind("--set needs BLOCK.NAME=VALUE", 0), 0u);
  EXPECT_EQ(error_of({"--set"}), "--set needs a value");
  EXPECT_EQ(error_of({"--setting="}).rfind("--setting needs a label", 0), 0u);
  EXPECT_EQ(error_of({"--set=a.b=1", "--setting=x"}).rfind("--set 'a.b=1' comes before", 0), 0u);
  EXPECT_EQ(error_of({"--final=a b"}), "--final needs vehicle names separated by commas: 'a b'");
  EXPECT_EQ(error_of({"--final=,"}).rfind("--final needs", 0), 0u);
  EXPECT_EQ(error_of({"--alog=x.alog", "--seeds=1..2"}),
            "--alog writes one mission: give --seed=N (not --seeds)");
  EXPECT_EQ(error_of({"--bogus"}), "unknown option '--bogus'");
  EXPECT_EQ(error_of({"other.moos"}), "unexpected argument 'other.moos'");
  EXPECT_EQ(parse_args({}).error, "missing MISSION.moos");
}

TEST(StudyArgs, HostileValuesAreBoundedInTheMessage) {
  const std::string huge(100000, 'x');
  EXPECT_LT(error_of({"--set=" + huge}).size(), 400u);
  EXPECT_LT(error_of({"--seeds=" + huge}).size(), 400u);
  EXPECT_LT(error_of({"--setting=" + huge}).size(), 400u);
  EXPECT_LT(error_of({"--" + huge}).size(), 400u);
}

TEST(StudyArgs, HelpAndVersionWinOverErrors) {
  EXPECT_TRUE(parse_args({"--bogus", "--help"}).options->help);
  EXPECT_TRUE(parse_args({"--set=bad", "--version"}).options->version);
}

}  // namespace
}  // namespace hazard_study
