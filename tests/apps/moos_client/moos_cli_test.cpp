// moos-cli option parsing, poke value typing and watch line formatting (no processes).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "MoosCli_Info.hpp"
#include "moos/alog.hpp"
#include "moos/alog_file.hpp"
#include "moos/limits.hpp"
#include "doc_tables.hpp"
#include "moos_cli.hpp"

namespace moos_cli {
namespace {

TEST(MoosCliOptions, PokeOptionsAndAssignments) {
  std::string error;
  const auto o = parse_options({"poke", "--host=10.1.1.1", "--port=9001", "--name=me", "--string",
                                "--connect-timeout=2.5", "A=1", "B=x"},
                               &error);
  ASSERT_TRUE(o.has_value()) << error;
  EXPECT_EQ(o->command, Command::kPoke);
  EXPECT_EQ(o->host, "10.1.1.1");
  EXPECT_EQ(o->port, 9001);
  EXPECT_EQ(o->name, "me");
  EXPECT_TRUE(o->all_strings);
  EXPECT_EQ(o->connect_timeout_s, 2.5);
  EXPECT_EQ(o->arguments, (std::vector<std::string>{"A=1", "B=x"}));
}

TEST(MoosCliOptions, WatchOptions) {
  std::string error;
  const auto o = parse_options({"watch", "--count=3", "--timeout=1.5", "NAV_*", "X"}, &error);
  ASSERT_TRUE(o.has_value()) << error;
  EXPECT_EQ(o->command, Command::kWatch);
  EXPECT_EQ(o->count, 3);
  EXPECT_EQ(o->timeout_s, 1.5);
  EXPECT_EQ(o->port, 9000);
  EXPECT_EQ(o->host, "localhost");
}

TEST(MoosCliOptions, UsageErrorsNameTheProblem) {
  std::string error;
  EXPECT_FALSE(parse_options({}, &error));
  EXPECT_EQ(error, "no command given");
  EXPECT_FALSE(parse_options({"peek"}, &error));
  EXPECT_EQ(error, "unknown command: peek");
  EXPECT_FALSE(parse_options({"poke", "--port=0", "A=1"}, &error));
  EXPECT_EQ(error, "bad port: --port=0");
  EXPECT_FALSE(parse_options({"poke", "--count=3", "A=1"}, &error));  // a watch option
  EXPECT_NE(error.find("unknown option for poke"), std::string::npos);
  EXPECT_FALSE(parse_options({"watch", "--count=0", "A"}, &error));
  EXPECT_FALSE(parse_options({"watch", "--timeout=-1", "A"}, &error));
  EXPECT_FALSE(parse_options({"watch"}, &error));
  EXPECT_EQ(error, "watch needs at least one variable or pattern");
  const auto help = parse_options({"poke", "--help"}, &error);
  ASSERT_TRUE(help.has_value());
  EXPECT_EQ(help->command, Command::kHelp);
}

TEST(MoosCliOptions, VersionIsACommandOfItsOwn) {
  std::string error;
  for (const char* v : {"--version", "-v", "-version"}) {
    const auto version = parse_options({v}, &error);
    ASSERT_TRUE(version.has_value()) << v << ": " << error;
    EXPECT_EQ(version->command, Command::kVersion) << v;
  }
  EXPECT_NE(help_text().find("moos-cli --version"), std::string::npos);
}

TEST(MoosCliOptions, EachSwitchProblemNamesSwitchAndValue) {
  std::string error;
  EXPECT_FALSE(parse_options({"poke", "--host=", "A=1"}, &error));
  EXPECT_EQ(error, "--host= needs a host");
  EXPECT_FALSE(parse_options({"watch", "A", "--count=0", "--timeout=-1"}, &error));
  EXPECT_EQ(error, "bad count: --count=0");  // the first problem
  EXPECT_FALSE(parse_options({"watch", "--timeout", "A"}, &error));
  EXPECT_EQ(error, "unknown option for watch: --timeout");
  EXPECT_FALSE(parse_options({"poke", "--moos_time_warp=401", "A=1"}, &error));
  EXPECT_EQ(error, "bad time warp: --moos_time_warp=401");
}

// A wait beyond kMaxRealWait_s overflowed the steady clock's deadline: moos-cli gave up at
// once. The bound itself is accepted.
TEST(MoosCliOptions, WaitsBeyondTheLargestAreRefused_Hardening) {
  std::string error;
  EXPECT_FALSE(parse_options({"watch", "A", "--timeout=1e300"}, &error));
  EXPECT_EQ(error, "bad timeout: --timeout=1e300");
  EXPECT_FALSE(parse_options({"watch", "A", "--connect-timeout=1e18"}, &error));
  EXPECT_EQ(error, "bad timeout: --connect-timeout=1e18");
  EXPECT_FALSE(parse_options({"poke", "--connect-timeout=1e300", "A=1"}, &error));
  const auto longest =
      parse_options({"watch", "A", "--timeout=1e8", "--connect-timeout=1e8"}, &error);
  ASSERT_TRUE(longest.has_value()) << error;
  EXPECT_EQ(longest->timeout_s, std::optional<double>(moos::kMaxRealWait_s));
}

TEST(MoosCliOptions, HelpWinsOverAProblemBesideIt) {
  // Settled with moosdb-lite and gen_hazards (docs/differences.md): --help anywhere wins.
  std::string error;
  const auto help = parse_options({"poke", "--port=0", "--help"}, &error);
  ASSERT_TRUE(help.has_value()) << error;
  EXPECT_EQ(help->command, Command::kHelp);
}

TEST(MoosCliPoke, NumbersAreDoublesUnlessQuotedOrForced) {
  std::string error;
  auto p = parse_poke("DEPTH=12.5", false, &error);
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(p->is_double);
  EXPECT_EQ(p->dval, 12.5);
  p = parse_poke("MODE=SURVEY", false, &error);
  EXPECT_FALSE(p->is_double);
  EXPECT_EQ(p->sval, "SURVEY");
  p = parse_poke("N=\"12\"", false, &error);
  EXPECT_FALSE(p->is_double);
  EXPECT_EQ(p->sval, "12");
  p = parse_poke("N:=12", false, &error);
  EXPECT_EQ(p->var, "N");
  EXPECT_FALSE(p->is_double);
  p = parse_poke("N=12", true, &error);
  EXPECT_FALSE(p->is_double);
  p = parse_poke("SPEC=a=b,c=d", false, &error);
  EXPECT_EQ(p->var, "SPEC");
  EXPECT_EQ(p->sval, "a=b,c=d");
  p = parse_poke("EMPTY=", false, &error);
  EXPECT_FALSE(p->is_double);
  EXPECT_EQ(p->sval, "");
  p = parse_poke("INF=inf", false, &error);
  EXPECT_FALSE(p->is_double);  // not a finite decimal: a string
  EXPECT_FALSE(parse_poke("NOEQUALS", false, &error));
  EXPECT_FALSE(parse_poke("=1", false, &error));
  EXPECT_FALSE(parse_poke(":=1", false, &error));
}

TEST(MoosCliWatch, ValuesAndLinesFollowTheHelpText) {
  moos::Message d = moos::make_double_notify("X", 0.1, "src", 1700000001.25);
  EXPECT_EQ(moos::alog_value(d), "0.1");
  moos::Message s = moos::make_string_notify("S", "a\nb", "src", 0);
  EXPECT_EQ(moos::alog_value(s), "a\nb");
  moos::Message b = moos::make_binary_notify("B", std::string("\x00\xff", 2), "src", 0);
  EXPECT_EQ(moos::alog_value(b), "<binary:2:00ff>");
  moos::Message u = d;
  u.data_type = moos::data_type::kNotSet;
  EXPECT_EQ(moos::alog_value(u), "<not set>");
  const std::string line = format_watch_line(d, 1700000000.0, 1700000002.0);
  const auto parsed = moos::parse_alog_line(line.substr(0, line.size() - 1));
  ASSERT_EQ(parsed.kind, moos::AlogLineKind::kEntry);
  EXPECT_DOUBLE_EQ(parsed.entry.time_s, 1.25);
  EXPECT_EQ(parsed.entry.variable, "X");
  EXPECT_EQ(parsed.entry.source, "src");
  EXPECT_EQ(parsed.entry.value, "0.1");
}

TEST(MoosCliWatch, ATimeNoLogReaderPlacesIsPrintedAtMoosCliClock) {
  const double start = 1700000000.0;
  const double now = start + 5.0;
  for (const double bad : {std::nan(""), -std::numeric_limits<double>::infinity(), 1e300,
                           now + 2 * moos::kAlogMaxClockSkew_s}) {
    const std::string line =
        format_watch_line(moos::make_double_notify("X", 1, "src", bad), start, now);
    const auto parsed = moos::parse_alog_line(line.substr(0, line.size() - 1));
    ASSERT_EQ(parsed.kind, moos::AlogLineKind::kEntry) << line;
    EXPECT_EQ(parsed.entry.time_s, 5.0) << bad;
  }
  // A time years before moos-cli's clock is some clock's time: printed as it is.
  const std::string old = format_watch_line(moos::make_double_notify("X", 1, "src", start - 1e8),
                                            start, now);
  EXPECT_EQ(moos::parse_alog_line(old.substr(0, old.size() - 1)).entry.time_s, -1e8) << old;
}

TEST(MoosCliInfo, HelpDocumentsEveryOptionAndExitCode) {
  const std::string help = help_text();
  for (const char* option : {"--host=", "--port=", "--name=", "--string", "--count=", "--timeout=",
                             "--connect-timeout=", "--moos_time_warp=", "<binary:N:HEX>"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
  for (int code : {kExitOk, kExitUsage, kExitWatchTimeout, kExitNoConnection, kExitRefused,
                   kExitNotWritten})
    EXPECT_NE(help.find(std::to_string(code) + " "), std::string::npos) << code;
}

TEST(MoosCliOptions, TheDocsSwitchTableIsTheSwitchTables) {
  const auto rows = test_support::doc_table(std::string(HAZARD_SOURCE_DIR) + "/docs/moos.md",
                                            "`moos-cli`");
  ASSERT_FALSE(rows.empty()) << "docs/moos.md: no table under '### `moos-cli`'";
  const auto poke = test_support::switches_of(switch_table(Command::kPoke), false);
  const auto watch = test_support::switches_of(switch_table(Command::kWatch), false);
  std::set<std::string> both = poke;
  both.insert(watch.begin(), watch.end());
  EXPECT_EQ(test_support::switches_in_first_column(rows), both);
  for (const auto& row : rows) {  // the Commands column
    ASSERT_GE(row.size(), 2u);
    for (const std::string& name : test_support::switches_named(row[0])) {
      EXPECT_EQ(poke.count(name) == 1, row[1] != "watch") << name;
      EXPECT_EQ(watch.count(name) == 1, row[1] != "poke") << name;
    }
  }
}

}  // namespace
}  // namespace moos_cli
