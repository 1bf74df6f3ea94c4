// pLogLite, the binary, against moosdb-lite: what it writes is what moosdb-lite's own --log
// writes for the same messages (same variables, sources, values, and the same absolute times),
// so a run on a real MOOSDB logged by pLogLite reads exactly like a run on moosdb-lite.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <tuple>

#include "alog_files.hpp"
#include "child_process.hpp"
#include "moosdb_server.hpp"
#include "scratch_files.hpp"

namespace plog_lite {
namespace {

using test_support::Alog;
using test_support::Child;
using test_support::MoosdbServer;
using test_support::read_alog;
using test_support::run_program;

/// (variable, source, value) -> absolute time, for the variables of interest.
std::map<std::tuple<std::string, std::string, std::string>, double> keyed(
    const Alog& log, const std::vector<std::string>& variables) {
  std::map<std::tuple<std::string, std::string, std::string>, double> out;
  for (const auto& e : log.entries)
    if (std::find(variables.begin(), variables.end(), e.variable) != variables.end())
      out[{e.variable, e.source, e.value}] = e.time_s + log.logstart_s;
  return out;
}

bool connected(int port, const std::string& name) {
  const auto watch = run_program(MOOS_CLI_PATH,
                                 {"watch", "--port=" + std::to_string(port), "--count=1",
                                  "--timeout=2", "DB_CLIENTS"},
                                 5.0);
  return watch.out.find(name) != std::string::npos;
}

TEST(LoggerProcess, WritesWhatMoosdbLiteLogsForTheSameMessages) {
  test_support::ScratchDir dir;
  const std::string db_log = (dir / "db.alog").string();
  MoosdbServer server(MOOSDB_LITE_PATH, {"--log=" + db_log, "--moos_community=logtest"});
  ASSERT_TRUE(server.ok());
  test_support::write_file(dir / "m.moos",
                           "ServerHost = localhost\nServerPort = " + std::to_string(server.port()) +
                               "\nCommunity = logtest\n\nProcessConfig = pLogLite\n{\n  path = " +
                               dir.path().string() +
                               "\n  file = plog\n  file_timestamp = false\n  wildcard_logging = true\n}\n");
  auto logger = Child::spawn(PLOGLITE_PATH, {(dir / "m.moos").string()});
  ASSERT_TRUE(logger);
  bool up = false;
  for (int i = 0; i < 50 && !up; ++i) {
    up = connected(server.port(), "pLogLite");
    if (!up) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(up) << logger->stderr_text();
  const auto poke = run_program(MOOS_CLI_PATH,
                                {"poke", "--port=" + std::to_string(server.port()), "--name=poker",
                                 "SPEED=1.5", "NOTE=a value with blanks", "LABEL:=12"},
                                10.0);
  ASSERT_EQ(poke.exit_code, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  logger->stop();
  server.stop();

  const std::vector<std::string> vars = {"SPEED", "NOTE", "LABEL"};
  const auto ours = keyed(read_alog(dir / "plog.alog"), vars);
  const auto theirs = keyed(read_alog(db_log), vars);
  ASSERT_EQ(ours.size(), 3u);
  ASSERT_EQ(theirs.size(), 3u);
  for (const auto& [key, time_s] : theirs) {
    const auto it = ours.find(key);
    ASSERT_NE(it, ours.end()) << std::get<0>(key) << " " << std::get<2>(key);
    EXPECT_NEAR(it->second, time_s, 2e-3);  // both write 3 decimals
  }
  EXPECT_EQ(ours.count({"SPEED", "poker", "1.5"}), 1u);
  EXPECT_EQ(ours.count({"LABEL", "poker", "12"}), 1u);
}

TEST(LoggerProcess, InformationSwitchesPrintAndExitZero) {
  for (const char* flag : {"--help", "-e", "-i", "-v"}) {
    auto c = Child::spawn(PLOGLITE_PATH, {flag});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->wait(10.0), 0) << flag;
    EXPECT_NE(c->stdout_text().find("pLogLite"), std::string::npos) << flag;
  }
}

}  // namespace
}  // namespace plog_lite
