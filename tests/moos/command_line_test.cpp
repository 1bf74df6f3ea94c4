// Command-line conventions: docs/protocol.md 6.4 and docs/uFldHazardSensor.md.
#include <gtest/gtest.h>

#include <set>

#include "doc_tables.hpp"
#include "moos/command_line.hpp"

namespace moos {
namespace {

CommandLine parse(std::vector<std::string> args) {
  args.insert(args.begin(), "uFldHazardSensor");
  return parse_command_line(args);
}

TEST(CommandLine, PantlerFormMissionThenAlias_6_4) {
  const auto cl = parse({"jake.moos", "uFldHazardSensor_2"});
  EXPECT_EQ(cl.mission_file, "jake.moos");
  EXPECT_EQ(cl.run_alias, "uFldHazardSensor_2");
  EXPECT_TRUE(cl.errors.empty());
  EXPECT_EQ(app_name_from(cl, "uFldHazardSensor"), "uFldHazardSensor_2");
}

TEST(CommandLine, MissionFoundByExtensionAnywhere_6_4) {
  const auto cl = parse({"--verbose", "other", "m.moos++"});
  EXPECT_EQ(cl.mission_file, "m.moos++");
  EXPECT_FALSE(cl.run_alias.has_value());  // the second free argument is the mission file
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
                         "--moos_quiet", "m.moos"});
  EXPECT_TRUE(cl.errors.empty());
  EXPECT_EQ(cl.moos_port, 9123);
  EXPECT_EQ(cl.moos_host, "127.0.0.1");
  EXPECT_EQ(cl.moos_time_warp, 10.0);
  EXPECT_EQ(cl.moos_app_tick_hz, 4.0);
  EXPECT_EQ(cl.moos_name, "pSensor");
  EXPECT_EQ(cl.moos_switches.at("moos_community"), "alpha");  // untyped: no program reads it
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
}

TEST(CommandLine, MoosFileSwitchNamesTheMission) {
  const auto cl = parse({"--moos_file=real.moos", "x.moos", "alias"});
  EXPECT_EQ(cl.mission_file, "real.moos");
  EXPECT_EQ(cl.run_alias, "alias");
}

TEST(CommandLine, ArgcArgvEntryPointMatchesTheVectorOne) {
  const char* argv[] = {"app", "m.moos", "pA", "--moos_port=9001"};
  const auto cl = parse_command_line(4, argv);
  EXPECT_EQ(cl.mission_file, "m.moos");
  EXPECT_EQ(cl.run_alias, "pA");
  EXPECT_EQ(cl.moos_port, 9001);
}

// ---- information switches (docs/uFldHazardSensor.md) --------------------------------------------

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
  // docs/uFldHazardSensor.md, "Usage": there is no one-dash -interface.
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

// ---- the typed switch table ------------------------------------------------------------------

SwitchRule rule(std::string name, SwitchKind kind, Range range = kAnyNumber) {
  return switch_rule(std::move(name), kind, "refused", range);
}

SwitchTable test_table() {
  SwitchTable t;
  t.rules = {rule("--port", SwitchKind::kInteger, kListenPortRange),
             rule("--warp", SwitchKind::kNumber, kTimeWarpRange),
             rule("--seed", SwitchKind::kUnsigned),
             rule("--name", SwitchKind::kText),
             rule("--help", SwitchKind::kFlag),
             rule("--dns", SwitchKind::kIgnored)};
  t.rules[4].aliases = {"-h"};
  t.rules[3].check = [](const std::string& v) { return v != "bad"; };
  t.bad_value = [](const std::string& a, const SwitchRule& r) { return a + ": " + r.problem; };
  t.missing_value = [](const std::string& a, const SwitchRule& r) { return a + " needs " + r.name + "=VALUE"; };
  t.unknown = [](const std::string& a) { return a + ": unknown"; };
  return t;
}

TEST(SwitchTable, TypedValuesAreReadWithTheRuleThatAcceptedThem) {
  const SwitchValues v = parse_switches(
      {"a.moos", "--port=0", "--warp=400", "--seed=18446744073709551615", "--name=x", "-h", "-",
       "--port=65535"},
      test_table());
  EXPECT_TRUE(v.errors.empty()) << v.errors.front();
  EXPECT_EQ(v.free, (std::vector<std::string>{"a.moos", "-"}));  // "-" alone is free
  EXPECT_EQ(v.integer("--port"), 65535);                            // the last one counts
  EXPECT_EQ(v.number("--warp"), 400.0);
  EXPECT_EQ(v.whole("--seed"), 18446744073709551615ull);
  EXPECT_EQ(v.text("--name"), "x");
  EXPECT_TRUE(v.has("--help"));  // by its alias
  EXPECT_FALSE(v.has("--dns"));
}

TEST(SwitchTable, EachProblemIsNamedInArgumentOrder) {
  const SwitchValues v = parse_switches(
      {"--port=65536", "--warp=0", "--name=", "--name=bad", "--seed=-1", "--port", "--help=yes",
       "--frob", "--dns=1.2.3.4"},
      test_table());
  EXPECT_EQ(v.errors, (std::vector<std::string>{
                          "--port=65536: refused", "--warp=0: refused", "--name=: refused",
                          "--name=bad: refused", "--seed=-1: refused", "--port needs --port=VALUE",
                          "--help=yes: unknown", "--frob: unknown"}));
  EXPECT_EQ(v.notes, (std::vector<std::string>{"--dns=1.2.3.4 ignored: refused"}));
  EXPECT_TRUE(v.values.empty());
}

TEST(SwitchTable, PortRangesOfClientsAndServers) {
  EXPECT_FALSE(kConnectPortRange.contains(0));
  EXPECT_TRUE(kListenPortRange.contains(0));
  EXPECT_TRUE(kConnectPortRange.contains(kMaxPort));
  EXPECT_FALSE(kListenPortRange.contains(kMaxPort + 1));
  const auto client = parse({"m.moos", "--moos_port=0"});
  ASSERT_EQ(client.errors.size(), 1u);
  EXPECT_EQ(client.errors[0], "--moos_port=0: not a port number in 1..65535");
}

TEST(SwitchTable, TheDocsGenericSwitchTableIsTheCode) {
  const auto rows = test_support::doc_table(std::string(HAZARD_SOURCE_DIR) + "/docs/moos.md",
                                            "Command line (`moos/command_line.hpp`)");
  ASSERT_FALSE(rows.empty()) << "docs/moos.md: no table of the generic switches";
  SwitchTable generic;
  generic.rules = generic_switch_rules();
  std::set<std::string> names = test_support::switches_of(generic, false);
  names.insert("--alias");  // read by parse_command_line itself
  EXPECT_EQ(test_support::switches_in_first_column(rows), names);
}

}  // namespace
}  // namespace moos
