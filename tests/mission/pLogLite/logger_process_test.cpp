// pLogLite, the binary, against moosdb-lite: what it writes is what moosdb-lite's own --log
// writes for the same messages (same variables, sources, values, and the same absolute times),
// so a run on a real MOOSDB logged by pLogLite reads exactly like a run on moosdb-lite.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <thread>
#include <tuple>

#include "app_on_bus.hpp"
#include "moos/alog.hpp"
#include "process_support.hpp"

namespace plog_lite {
namespace {

using moos::process_test::Child;
using moos::process_test::run_cli;
using moos::process_test::Server;

struct Log {
  double logstart_s = 0.0;
  std::vector<moos::AlogEntry> entries;
};

Log read_log(const std::string& path) {
  Log log;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (auto start = moos::alog_logstart(line)) log.logstart_s = *start;
    const auto p = moos::parse_alog_line(line);
    if (p.kind == moos::AlogLineKind::kEntry) log.entries.push_back(p.entry);
  }
  return log;
}

/// (variable, source, value) -> absolute time, for the variables of interest.
std::map<std::tuple<std::string, std::string, std::string>, double> keyed(
    const Log& log, const std::vector<std::string>& variables) {
  std::map<std::tuple<std::string, std::string, std::string>, double> out;
  for (const auto& e : log.entries)
    if (std::find(variables.begin(), variables.end(), e.variable) != variables.end())
      out[{e.variable, e.source, e.value}] = e.time_s + log.logstart_s;
  return out;
}

bool connected(int port, const std::string& name) {
  std::optional<int> code;
  Child c = run_cli({"watch", "--port=" + std::to_string(port), "--count=1", "--timeout=2",
                     "DB_CLIENTS"},
                    5.0, &code);
  return c.stdout_text().find(name) != std::string::npos;
}

TEST(LoggerProcess, WritesWhatMoosdbLiteLogsForTheSameMessages) {
  mission_test::ScratchDir dir;
  const std::string db_log = (dir / "db.alog").string();
  auto server = Server::start(0, {"--log=" + db_log, "--moos_community=logtest"});
  ASSERT_TRUE(server);
  mission_test::write_file(dir / "m.moos",
                           "ServerHost = localhost\nServerPort = " + std::to_string(server->port()) +
                               "\nCommunity = logtest\n\nProcessConfig = pLogLite\n{\n  path = " +
                               dir.path().string() +
                               "\n  file = plog\n  file_timestamp = false\n  wildcard_logging = true\n}\n");
  auto logger = Child::spawn(PLOGLITE_PATH, {(dir / "m.moos").string()});
  ASSERT_TRUE(logger);
  bool up = false;
  for (int i = 0; i < 50 && !up; ++i) {
    up = connected(server->port(), "pLogLite");
    if (!up) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(up) << logger->stderr_text();
  std::optional<int> code;
  run_cli({"poke", "--port=" + std::to_string(server->port()), "--name=poker", "SPEED=1.5",
           "NOTE=a value with blanks", "LABEL:=12"},
          10.0, &code);
  ASSERT_EQ(code, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  logger->stop();
  server->process().stop();

  const std::vector<std::string> vars = {"SPEED", "NOTE", "LABEL"};
  const auto ours = keyed(read_log((dir / "plog.alog").string()), vars);
  const auto theirs = keyed(read_log(db_log), vars);
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
