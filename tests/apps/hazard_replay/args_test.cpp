// hazard_replay's command line: exactly the issue's form; each bad option named.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "HazardReplay_Info.hpp"
#include "args.hpp"
#include "doc_tables.hpp"

namespace hazard_replay {
namespace {

TEST(ReplayArgs, IssueFormWithEveryOption) {
  const ParsedArgs p = parse_args({"m.moos", "in.alog", "--alias=shore", "--seed=42",
                                   "--until=120.5", "--output=out.alog"});
  ASSERT_TRUE(p.options) << p.error;
  EXPECT_EQ(p.options->config_path, "m.moos");
  EXPECT_EQ(p.options->input_path, "in.alog");
  EXPECT_EQ(p.options->app_name, "shore");
  EXPECT_EQ(p.options->seed, 42u);
  EXPECT_EQ(p.options->until_s, 120.5);
  EXPECT_EQ(p.options->output_path, "out.alog");
}

TEST(ReplayArgs, Defaults) {
  const ParsedArgs p = parse_args({"m.moos", "in.alog"});
  ASSERT_TRUE(p.options);
  EXPECT_EQ(p.options->app_name, "uFldHazardSensor");
  EXPECT_FALSE(p.options->seed);
  EXPECT_FALSE(p.options->until_s);
  EXPECT_FALSE(p.options->output_path);
}

TEST(ReplayArgs, BadArgumentsAreNamed) {
  struct Case {
    std::vector<std::string> args;
    const char* error;
  };
  const Case cases[] = {
      {{}, "missing CONFIG.moos and INPUT.alog"},
      {{"m.moos"}, "missing INPUT.alog"},
      {{"m.moos", "in.alog", "extra"}, "unexpected argument 'extra'"},
      {{"m.moos", "in.alog", "--seed=abc"}, "'--seed=abc'"},
      {{"m.moos", "in.alog", "--seed=-1"}, "'--seed=-1'"},
      {{"m.moos", "in.alog", "--until=nan"}, "'--until=nan'"},
      {{"m.moos", "in.alog", "--until=1e999"}, "'--until=1e999'"},
      {{"m.moos", "in.alog", "--alias="}, "'--alias='"},
      {{"m.moos", "in.alog", "--output="}, "'--output='"},
      {{"m.moos", "in.alog", "--verbose"}, "unknown option '--verbose'"},
      {{"m.moos", "in.alog", "--seed"}, "unknown option '--seed'"},
      {{"m.moos", "in.alog", "--seed=abc"}, "--seed needs a whole number in [0, 2^64): '--seed=abc'"},
      {{"m.moos", "in.alog", "--help=yes"}, "unknown option '--help=yes'"},
  };
  for (const Case& c : cases) {
    const ParsedArgs p = parse_args(c.args);
    EXPECT_FALSE(p.options);
    EXPECT_NE(p.error.find(c.error), std::string::npos) << p.error;
  }
}

TEST(ReplayArgs, CapitalisedNameValueArgumentsAreMissionSubstitutions) {
  const ParsedArgs p =
      parse_args({"--PORT=9000", "m.moos", "in.alog", "--SEED=3", "--View_2=a=b", "--seed=4"});
  ASSERT_TRUE(p.options) << p.error;
  const std::map<std::string, std::string> expected = {
      {"PORT", "9000"}, {"SEED", "3"}, {"View_2", "a=b"}};
  EXPECT_EQ(p.options->substitutions, expected);
  EXPECT_EQ(p.options->seed, 4u);  // the switch, not the macro of the same name in capitals
  EXPECT_EQ(p.options->config_path, "m.moos");
}

TEST(ReplayArgs, LowerCaseOrMalformedNameValueArgumentsStayErrors) {
  for (const char* arg : {"--port=9000", "--P-ORT=1", "--PORT", "--_X=1"}) {
    const ParsedArgs p = parse_args({"m.moos", "in.alog", arg});
    EXPECT_FALSE(p.options) << arg;
    EXPECT_NE(p.error.find(arg), std::string::npos) << p.error;
  }
}

TEST(ReplayArgs, HelpNeedsNoFiles) {
  for (const char* h : {"--help", "-h"}) {
    const ParsedArgs p = parse_args({h});
    ASSERT_TRUE(p.options);
    EXPECT_TRUE(p.options->help);
  }
  // --help wins over a problem beside it (settled with moosdb-lite, moos-cli, gen_hazards).
  const ParsedArgs bad_and_help = parse_args({"--seed=x", "-h"});
  ASSERT_TRUE(bad_and_help.options) << bad_and_help.error;
  EXPECT_TRUE(bad_and_help.options->help);
  EXPECT_NE(help_text().find(usage_line()), std::string::npos);
  EXPECT_NE(help_text().find("--until=T"), std::string::npos);
}

TEST(ReplayArgs, VersionNeedsNoFilesAndHelpWinsOverIt) {
  for (const char* v : {"--version", "-v", "-version"}) {
    const ParsedArgs p = parse_args({v});
    ASSERT_TRUE(p.options) << v << ": " << p.error;
    EXPECT_TRUE(p.options->version) << v;
    EXPECT_FALSE(p.options->help) << v;
  }
  const ParsedArgs both = parse_args({"--version", "--help"});
  ASSERT_TRUE(both.options);
  EXPECT_TRUE(both.options->help);
  EXPECT_FALSE(both.options->version);
  EXPECT_NE(help_text().find("--version"), std::string::npos);
}

TEST(ReplayArgs, TheDocsSwitchTableIsTheSwitchTable) {
  const auto rows = test_support::doc_table(
      std::string(HAZARD_SOURCE_DIR) + "/docs/configuration.md", "Running offline: hazard_replay");
  ASSERT_FALSE(rows.empty()) << "docs/configuration.md: no switch table for hazard_replay";
  EXPECT_EQ(test_support::switches_in_first_column(rows),
            test_support::switches_of(switch_table(), false));
}

}  // namespace
}  // namespace hazard_replay

namespace hazard_replay {
namespace {

TEST(ReplayArgs, SeedsTakeARange) {
  const ParsedArgs p = parse_args({"m.moos", "in.alog", "--seeds=3..7"});
  ASSERT_TRUE(p.options) << p.error;
  ASSERT_TRUE(p.options->seeds);
  EXPECT_EQ(p.options->seeds->first, 3u);
  EXPECT_EQ(p.options->seeds->last, 7u);
  EXPECT_TRUE(parse_args({"m.moos", "in.alog", "--seeds=5..5"}).options);
  for (const char* bad : {"--seeds=7..3", "--seeds=3", "--seeds=a..b", "--seeds=1..",
                          "--seeds=0..1000000", "--seeds=-1..2"}) {
    const ParsedArgs q = parse_args({"m.moos", "in.alog", bad});
    EXPECT_FALSE(q.options) << bad;
    EXPECT_NE(q.error.find(std::string("'") + bad + "'"), std::string::npos) << q.error;
  }
  const ParsedArgs both = parse_args({"m.moos", "in.alog", "--seed=1", "--seeds=1..2"});
  EXPECT_EQ(both.error, "--seed and --seeds exclude each other");
}

}  // namespace
}  // namespace hazard_replay
