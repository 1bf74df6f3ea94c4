// pLogLite's app class on the in-process bus with a manual clock: the .alog it writes (header,
// LOGSTART, one line per message in pLogger's format), what it logs (wildcard, `log` lines, omit
// patterns), the file name, and its configuration warnings.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <regex>

#include "LogLite.hpp"
#include "LogLite_Info.hpp"
#include "app_on_bus.hpp"
#include "moos/alog.hpp"

namespace plog_lite {
namespace {

using mission_test::any_contains;
using mission_test::Bus;
using mission_test::example_block;
using mission_test::mission_text;
using test_support::read_file;

struct Logged {
  std::vector<std::string> headers;
  std::vector<moos::AlogEntry> entries;
};

Logged parse(const std::string& text) {
  Logged out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto p = moos::parse_alog_line(line);
    if (p.kind == moos::AlogLineKind::kHeader) out.headers.push_back(line);
    if (p.kind == moos::AlogLineKind::kEntry) out.entries.push_back(p.entry);
    EXPECT_NE(p.kind, moos::AlogLineKind::kMalformed) << line;
  }
  return out;
}

class LoggerOnBus : public ::testing::Test {
 protected:
  bool start(const std::string& block, std::shared_ptr<LogOutcome> outcome = nullptr) {
    app.emplace(std::move(outcome));
    return bus.start(*app, kAppName, mission_text(kAppName, "  path = " + bus.dir.path().string() +
                                                                "/logs\n" + block));
  }
  /// The variables logged, in order, without the framework's own postings.
  std::vector<std::string> logged_variables() const {
    std::vector<std::string> out;
    for (const auto& e : parse(read_file(app->file_path())).entries)
      if (e.source == "peer") out.push_back(e.variable);
    return out;
  }
  Bus bus;
  std::optional<LogLite> app;
};

TEST_F(LoggerOnBus, WritesPLoggersAlogWithLogstartAndRelativeTimes) {
  ASSERT_TRUE(start("  file = run\n  file_timestamp = false\n  wildcard_logging = true\n"));
  EXPECT_EQ(app->file_path(), (bus.dir / "logs/run.alog").string());
  app->run_for(2.0);
  bus.post("SPEED", 1.5);
  bus.post("NOTE", "a value with blanks");
  app->run_for(1.0);
  const Logged log = parse(read_file(app->file_path()));
  ASSERT_GE(log.headers.size(), 2u);
  EXPECT_NEAR(moos::alog_logstart(log.headers[1]).value_or(0.0), app->start_time(), 5e-4);
  std::vector<moos::AlogEntry> mine;
  for (const auto& e : log.entries)
    if (e.source == "peer") mine.push_back(e);
  ASSERT_EQ(mine.size(), 2u);
  EXPECT_EQ(mine[0].variable, "SPEED");
  EXPECT_EQ(mine[0].value, "1.5");
  EXPECT_NEAR(mine[0].time_s, 2.0, 1e-3);  // posted 2 s after start-up
  EXPECT_EQ(mine[1].value, "a value with blanks");
  EXPECT_EQ(app->records_written(), log.entries.size());
}

TEST_F(LoggerOnBus, ADeletedLogFolderIsARunWarningAndTheReportAndTheOutcomeCountTheLoss) {
  const auto outcome = std::make_shared<LogOutcome>();
  ASSERT_TRUE(start("  file = run\n  file_timestamp = false\n  wildcard_logging = true\n", outcome));
  bus.post("BEFORE", 1.0);
  app->run_for(1.0);
  std::filesystem::remove_all(bus.dir / "logs");
  bus.post("AFTER", 2.0);
  app->run_for(1.0);
  EXPECT_EQ(logged_variables(), std::vector<std::string>{"AFTER"});
  const std::uint64_t lost = app->records_lost();
  EXPECT_GT(lost, 0u);
  bool warned = false;
  for (const auto& [text, count] : app->appcast().run_warnings())
    warned = warned || text.find("deleted") != std::string::npos;
  EXPECT_TRUE(warned);
  const std::string report = app->terminal_report();
  EXPECT_NE(report.find(std::to_string(lost) + " lost"), std::string::npos) << report;
  app.reset();  // closes the log: the outcome main turns into the exit status
  EXPECT_EQ(outcome->records_lost, lost);
  EXPECT_NE(outcome->problem.find("records lost"), std::string::npos) << outcome->problem;
}

TEST_F(LoggerOnBus, OmitPatternsAreNotWritten) {
  ASSERT_TRUE(start("  file = run\n  file_timestamp = false\n  wildcard_logging = true\n"
                    "  wildcard_omit_pattern = *_ITER_GAP, DB_*\n"));
  bus.post("X_ITER_GAP", 1.0);
  bus.post("DB_TIME", 2.0);
  bus.post("KEEP", 3.0);
  app->run_for(1.0);
  EXPECT_EQ(logged_variables(), std::vector<std::string>{"KEEP"});
}

TEST_F(LoggerOnBus, LogLinesWithoutWildcardLogOnlyThoseVariables) {
  ASSERT_TRUE(start("  file = run\n  file_timestamp = false\n  log = A @ 0\n  log = B\n"));
  bus.post("A", 1.0);
  bus.post("B", "two");
  bus.post("C", 3.0);
  app->run_for(1.0);
  EXPECT_EQ(logged_variables(), (std::vector<std::string>{"A", "B"}));
}

TEST_F(LoggerOnBus, FileTimestampAppendsTheDateAndTime) {
  ASSERT_TRUE(start("  file = run\n  wildcard_logging = true\n"));
  EXPECT_TRUE(std::regex_search(app->file_path(),
                                std::regex(R"(/run_\d{4}_\d{2}_\d{2}_____\d{2}_\d{2}_\d{2}\.alog$)")))
      << app->file_path();
}

TEST_F(LoggerOnBus, NothingToLogIsAConfigWarning) {
  ASSERT_TRUE(start("  file = run\n  file_timestamp = false\n"));
  EXPECT_TRUE(any_contains(app->appcast().config_warnings(), "nothing to log"));
}

TEST_F(LoggerOnBus, BadLinesAreConfigWarningsNamingFileAndLine) {
  ASSERT_TRUE(start("  file = run\n  file_timestamp = maybe\n  log = A @ -1\n  async_log = false\n"
                    "  colour = red\n  wildcard_logging = true\n"));
  const auto& w = app->appcast().config_warnings();
  const std::string at = (bus.dir / "m.moos").string() + ":";
  const int first = mission_test::first_block_line();  // the path line
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 2) + ": parameter file_timestamp='maybe'"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 3) + ": parameter log='A @ -1'"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 4) + ": async_log = false"));
  EXPECT_TRUE(any_contains(w, at + std::to_string(first + 5) + ": unknown parameter 'colour'"));
}

TEST_F(LoggerOnBus, AFileThatCannotBeCreatedFailsTheStartUp) {
  test_support::write_file(bus.dir / "blocker", "a file, not a folder");
  app.emplace();
  EXPECT_FALSE(bus.start(*app, kAppName,
                         mission_text(kAppName, "  path = " + (bus.dir / "blocker").string() +
                                                    "\n  wildcard_logging = true\n")));
  EXPECT_TRUE(any_contains(app->appcast().config_warnings(),
                           "the log file: cannot write '" + (bus.dir / "blocker").string() + "/"));
}

TEST(LoggerParse, LogRequests) {
  EXPECT_EQ(parse_log_request("NAV_X @ 0.5")->interval_s, 0.5);
  EXPECT_EQ(parse_log_request("NAV_X")->variable, "NAV_X");
  EXPECT_FALSE(parse_log_request("@ 1"));
  EXPECT_FALSE(parse_log_request("A B @ 1"));
  EXPECT_FALSE(parse_log_request("A @ soon"));
  EXPECT_EQ(file_time_stamp(0.0).size(), std::string("_1970_01_01_____00_00_00").size());
}

TEST(LoggerInfo, ExampleBlockLoadsWithoutWarnings_Practice5) {
  auto block = example_block(example_text());
  ASSERT_TRUE(block);
  Bus bus;
  // The example logs to the current folder; here, to the scratch folder.
  block->replace(block->find("path"), std::string("path").size(), "// path");
  LogLite app;
  ASSERT_TRUE(bus.start(app, kAppName,
                        mission_text(kAppName, "  path = " + bus.dir.path().string() + "\n" + *block)));
  EXPECT_TRUE(app.appcast().config_warnings().empty())
      << ::testing::PrintToString(app.appcast().config_warnings());
}

}  // namespace
}  // namespace plog_lite
