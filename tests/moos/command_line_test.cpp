// Command-line conventions: wire spec 6.4 and hazard spec 2.
#include <gtest/gtest.h>

#include "moos/command_line.hpp"

namespace moos {
namespace {

CommandLine parse(std::vector<std::string> args) {
  args.insert(args.begin(), "uFldHazardSensor");
  return parse_command_line(args);
}

TEST(CommandLine, PantlerFormMissionThenAlias_6_4) {
  const auto cl = parse({"jake.moos", "uFldHazardSensor_2"});
  EXPECT_EQ(cl.program, "uFldHazardSensor");
  EXPECT_EQ(cl.mission_file, "jake.moos");
  EXPECT_EQ(cl.run_alias, "uFldHazardSensor_2");
  EXPECT_TRUE(cl.extra_arguments.empty());
  EXPECT_TRUE(cl.errors.empty());
  EXPECT_EQ(app_name_from(cl, "uFldHazardSensor"), "uFldHazardSensor_2");
}

TEST(CommandLine, MissionFoundByExtensionAnywhere_6_4) {
  const auto cl = parse({"--verbose", "other", "m.moos++"});
  EXPECT_EQ(cl.mission_file, "m.moos++");
  EXPECT_FALSE(cl.run_alias.has_value());  // the second free argument is the mission file
  EXPECT_EQ(cl.extra_arguments, std::vector<std::string>{"other"});
  EXPECT_EQ(app_name_from(cl, "uFldHazardSensor"), "uFldHazardSensor");
}

TEST(CommandLine, FirstFreeArgumentIsTheMissionWithoutExtension_6_4) {
  const auto cl = parse({"Mission.txt", "pAlias"});
  EXPECT_EQ(cl.mission_file, "Mission.txt");
  EXPECT_EQ(cl.run_alias, "pAlias");
}

TEST(CommandLine, AliasFlagBeatsThePositionalAlias_2) {
  const auto cl = parse({"m.moos", "positional", "--alias=uFldHazardSensorB"});
  EXPECT_EQ(cl.run_alias, "uFldHazardSensorB");
  EXPECT_EQ(cl.extra_arguments, std::vector<std::string>{"positional"});
}

TEST(CommandLine, NoArgumentsMeansNoMission) {
  const auto cl = parse({});
  EXPECT_FALSE(cl.mission_file.has_value());
  EXPECT_FALSE(cl.run_alias.has_value());
  EXPECT_TRUE(cl.unhandled.empty());
}

TEST(CommandLine, GenericMoosSwitchesAreTyped_6_4) {
  const auto cl = parse({"--moos_port=9123", "--moos_host=127.0.0.1", "--moos_time_warp=10",
                         "--moos_app_tick=4", "--moos_name=pSensor", "--moos_community=alpha",
                         "--moos_timeout=3", "--moos_quiet", "m.moos"});
  EXPECT_TRUE(cl.errors.empty());
  EXPECT_EQ(cl.moos_port, 9123);
  EXPECT_EQ(cl.moos_host, "127.0.0.1");
  EXPECT_EQ(cl.moos_time_warp, 10.0);
  EXPECT_EQ(cl.moos_app_tick_hz, 4.0);
  EXPECT_EQ(cl.moos_name, "pSensor");
  EXPECT_EQ(cl.moos_community, "alpha");
  EXPECT_EQ(cl.moos_timeout_s, 3.0);
  EXPECT_EQ(cl.moos_switches.at("moos_quiet"), "");
  EXPECT_TRUE(cl.unhandled.empty());  // generic switches are not the app's business
  EXPECT_TRUE(cl.substitutions.empty());
  EXPECT_EQ(cl.mission_file, "m.moos");
}

TEST(CommandLine, SwitchesReadFromTheNextArgument_6_4) {
  const auto cl = parse({"m.moos", "--moos_app_name", "pNamed", "--moos_comms_tick", "20"});
  EXPECT_EQ(cl.moos_app_name, "pNamed");
  EXPECT_EQ(cl.moos_comms_tick_hz, 20);
  EXPECT_FALSE(cl.run_alias.has_value());
  EXPECT_TRUE(cl.extra_arguments.empty());
  EXPECT_EQ(app_name_from(cl, "x"), "pNamed");
}

TEST(CommandLine, BadSwitchValuesAreErrorsNamingTheArgument) {
  const auto cl = parse({"--moos_port=abc", "--moos_time_warp=0", "--moos_time_warp=401",
                         "--moos_app_tick=-1", "--moos_port=70000", "--alias=", "--moos_comms_tick"});
  ASSERT_EQ(cl.errors.size(), 7u);
  EXPECT_EQ(cl.errors[0], "--moos_port=abc: not a port number in 1..65535");
  EXPECT_NE(cl.errors[1].find("--moos_time_warp=0"), std::string::npos);
  EXPECT_NE(cl.errors[6].find("--moos_comms_tick"), std::string::npos);
  EXPECT_FALSE(cl.moos_port.has_value());
  EXPECT_FALSE(cl.moos_time_warp.has_value());
  EXPECT_FALSE(cl.moos_app_tick_hz.has_value());
  EXPECT_FALSE(cl.run_alias.has_value());
}

TEST(CommandLine, NameValueArgumentsAreSubstitutionsAndVisibleToTheApp) {
  const auto cl = parse({"m.moos", "--VNAME=archie", "--verbose=true", "--help", "-e"});
  EXPECT_EQ(cl.substitutions.at("VNAME"), "archie");
  EXPECT_EQ(cl.substitutions.at("verbose"), "true");
  EXPECT_EQ(cl.unhandled,
            (std::vector<std::string>{"--VNAME=archie", "--verbose=true", "--help", "-e"}));
  EXPECT_TRUE(cl.has_flag("--help", {"-h"}));
  EXPECT_TRUE(cl.has_flag("--example", {"-e", "-example"}));
  EXPECT_FALSE(cl.has_flag("--interface", {"-i"}));
  EXPECT_EQ(cl.flag_value("--verbose"), "true");
  EXPECT_FALSE(cl.flag_value("--other").has_value());
}

TEST(CommandLine, MoosFileSwitchNamesTheMission) {
  const auto cl = parse({"--moos_file=real.moos", "x.moos", "alias"});
  EXPECT_EQ(cl.mission_file, "real.moos");
  EXPECT_EQ(cl.run_alias, "alias");
  EXPECT_EQ(cl.extra_arguments, std::vector<std::string>{"x.moos"});
}

TEST(CommandLine, ArgcArgvEntryPointMatchesTheVectorOne) {
  const char* argv[] = {"app", "m.moos", "pA", "--moos_port=9001"};
  const auto cl = parse_command_line(4, argv);
  EXPECT_EQ(cl.mission_file, "m.moos");
  EXPECT_EQ(cl.run_alias, "pA");
  EXPECT_EQ(cl.moos_port, 9001);
}

// ---- information switches (hazard spec 2) ------------------------------------------------------

TEST(InformationSwitch, EveryFormOfTheMoosIvpConvention_Spec2) {
  for (const char* a : {"-e", "--example", "-example"})
    EXPECT_EQ(information_switch(a), InfoSwitch::kExample) << a;
  for (const char* a : {"-h", "--help", "-help"})
    EXPECT_EQ(information_switch(a), InfoSwitch::kHelp) << a;
  for (const char* a : {"-i", "--interface"})
    EXPECT_EQ(information_switch(a), InfoSwitch::kInterface) << a;
  for (const char* a : {"-v", "--version", "-version"})
    EXPECT_EQ(information_switch(a), InfoSwitch::kVersion) << a;
}

TEST(InformationSwitch, OnlyWholeWordsInTheirExactCaseCount_Spec2) {
  // Spec 2: there is no one-dash -interface.
  for (const char* a : {"-interface", "--Help", "-H", "--help=yes", "--versions", "help", "-", ""})
    EXPECT_FALSE(information_switch(a).has_value()) << a;
}

TEST(InformationSwitch, TheFirstOnTheCommandLineDecides_Spec2) {
  EXPECT_EQ(first_information_switch(parse({"m.moos", "--version", "--help"})),
            InfoSwitch::kVersion);
  EXPECT_EQ(first_information_switch(parse({"-i", "m.moos", "-e"})), InfoSwitch::kInterface);
  EXPECT_EQ(first_information_switch(parse({"--verbose", "-example"})), InfoSwitch::kExample);
}

TEST(InformationSwitch, NoneWhenTheCommandLineHasNone_Spec2) {
  EXPECT_FALSE(first_information_switch(parse({})).has_value());
  EXPECT_FALSE(first_information_switch(parse({"m.moos", "-interface", "--VNAME=-h"})).has_value());
  // Free arguments are mission files and aliases, never switches.
  EXPECT_FALSE(first_information_switch(parse({"help", "version"})).has_value());
}

TEST(DecideLaunch, RunsWithAMissionFileAndShowsTheHelpWithout_Spec2) {
  EXPECT_EQ(decide_launch(parse({"m.moos"})), LaunchAction::kRun);
  EXPECT_EQ(decide_launch(parse({"m.moos", "alias"})), LaunchAction::kRun);
  EXPECT_EQ(decide_launch(parse({})), LaunchAction::kHelp);
  EXPECT_EQ(decide_launch(parse({"--moos_port=9001"})), LaunchAction::kHelp);
}

TEST(DecideLaunch, AnInformationSwitchWinsOverAMissionFile_Spec2) {
  EXPECT_EQ(decide_launch(parse({"m.moos", "-e", "--help"})), LaunchAction::kExample);
  EXPECT_EQ(decide_launch(parse({"m.moos", "-help"})), LaunchAction::kHelp);
  EXPECT_EQ(decide_launch(parse({"--interface", "-v"})), LaunchAction::kInterface);
  EXPECT_EQ(decide_launch(parse({"-version"})), LaunchAction::kVersion);
}

}  // namespace
}  // namespace moos
