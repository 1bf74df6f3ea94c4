// uFldHazardSensor's command line (manual 11, listing 11.4; D29),
// decided without
// running anything.
#include <gtest/gtest.h>

#include "HazardSensor_Info.hpp"
#include "launch.hpp"
#include "moos/command_line.hpp"

namespace ufld_hazard_sensor {
namespace {

Launch launch_for(std::vector<std::string> args) {
  args.insert(args.begin(), "uFldHazardSensor");
  return decide_launch_with_verbosity(moos::parse_command_line(args));
}

TEST(Launch, InformationSwitchesInEveryForm_Spec2) {
  for (const char* a : {"-e", "--example", "-example"})
    EXPECT_EQ(launch_for({a}).action, LaunchAction::kExample) << a;
  for (const char* a : {"-h", "--help", "-help"})
    EXPECT_EQ(launch_for({a}).action, LaunchAction::kHelp) << a;
  for (const char* a : {"-i", "--interface"})
    EXPECT_EQ(launch_for({a}).action, LaunchAction::kInterface) << a;
  for (const char* a : {"-v", "--version", "-version"})
    EXPECT_EQ(launch_for({a}).action, LaunchAction::kVersion) << a;
  // There is no one-dash -interface (docs/uFldHazardSensor.md, "Usage").
  EXPECT_EQ(launch_for({"m.moos", "-interface"}).action, LaunchAction::kRun);
}

TEST(Launch, TheFirstInformationSwitchWinsEvenWithAMissionFile_Spec2) {
  EXPECT_EQ(launch_for({"m.moos", "--version", "--help"}).action, LaunchAction::kVersion);
  EXPECT_EQ(launch_for({"-i", "m.moos", "-e"}).action, LaunchAction::kInterface);
}

TEST(Launch, NoMissionFileShowsTheHelp_Spec2) {
  EXPECT_EQ(launch_for({}).action, LaunchAction::kHelp);
  EXPECT_EQ(launch_for({"--verbose"}).action, LaunchAction::kHelp);
}

TEST(Launch, AMissionFileRuns) {
  const Launch l = launch_for({"m.moos"});
  EXPECT_EQ(l.action, LaunchAction::kRun);
  EXPECT_FALSE(l.verbose);
}

TEST(Launch, VerboseForms_D29) {
  EXPECT_TRUE(launch_for({"m.moos", "--verbose"}).verbose);  // a bare --verbose means true
  EXPECT_TRUE(launch_for({"m.moos", "--verbose=true"}).verbose);
  EXPECT_TRUE(launch_for({"m.moos", "--verbose=TRUE"}).verbose);
  EXPECT_FALSE(launch_for({"m.moos", "--verbose=false"}).verbose);
  EXPECT_FALSE(launch_for({"m.moos", "--verbose", "--verbose=false"}).verbose);  // the last wins
}

TEST(Launch, ABadVerboseValueIsAUsageErrorNamingIt_D29) {
  const Launch l = launch_for({"m.moos", "--verbose=loud"});
  EXPECT_EQ(l.action, LaunchAction::kUsageError);
  EXPECT_EQ(l.error, "'--verbose=loud': the verbosity must be true or false");
}

TEST(Launch, VerboseIsNeverTheRunAliasButArgv2Is_D29) {
  // The original took a second-place --verbose for the process name; we do not.
  const auto cl = moos::parse_command_line({"uFldHazardSensor", "m.moos", "--verbose"});
  EXPECT_FALSE(cl.run_alias.has_value());
  EXPECT_EQ(moos::app_name_from(cl, kAppName), "uFldHazardSensor");
  const auto antler = moos::parse_command_line({"uFldHazardSensor", "m.moos", "uFldHazardSensor_2"});
  EXPECT_EQ(moos::app_name_from(antler, kAppName), "uFldHazardSensor_2");
  const auto alias = moos::parse_command_line({"uFldHazardSensor", "--alias=uHZ", "m.moos"});
  EXPECT_EQ(moos::app_name_from(alias, kAppName), "uHZ");
  EXPECT_EQ(decide_launch_with_verbosity(alias).action, LaunchAction::kRun);
}

TEST(Launch, UnknownFlagsAreIgnoredAsInTheOriginal_Spec2) {
  const Launch l = launch_for({"m.moos", "-x", "--something=else"});
  EXPECT_EQ(l.action, LaunchAction::kRun);
  EXPECT_FALSE(l.verbose);
}

}  // namespace
}  // namespace ufld_hazard_sensor
