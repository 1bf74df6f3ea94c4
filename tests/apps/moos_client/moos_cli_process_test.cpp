// moos-cli as a process against moosdb-lite: poke and watch, their output and exit codes
// (documented in src/apps/moos-cli/MoosCli_Info.cpp).
#include <gtest/gtest.h>

#include <thread>

#include "alog_files.hpp"
#include "child_process.hpp"
#include "moos/tcp_client.hpp"
#include "moosdb_server.hpp"

namespace moos {
namespace {

using test_support::alog_entries;
using test_support::Child;
using test_support::local_client_options;
using test_support::MoosdbServer;
using test_support::run_program;
using test_support::RunResult;
using test_support::steady_now_s;

constexpr double kRun_s = 20.0;  // bound on any single moos-cli run

RunResult run_cli(const std::vector<std::string>& args) {
  return run_program(MOOS_CLI_PATH, args, kRun_s);
}

/// Waits until moos-cli watch `name` has subscribed to `last_var`, the last variable it
/// registers: DB_RWSUMMARY lists it among the client's subscriptions (`name=A:B&...`). Its name
/// in DB_CLIENTS is not enough: the watch may not have registered, nor taken its start time.
bool wait_for_subscriber(int port, const std::string& name, const std::string& last_var) {
  TcpClient probe(local_client_options(port, "probe_" + name));
  if (!probe.start() || !probe.wait_until_connected(5.0)) return false;
  probe.register_variable("DB_RWSUMMARY");
  const double deadline = steady_now_s() + 10.0;
  while (steady_now_s() < deadline) {
    probe.notify("PROBE_TICK", 1.0);  // DB variables refresh on traffic in the reference DB
    for (const auto& m : probe.fetch()) {
      if (m.key != "DB_RWSUMMARY") continue;
      const std::string list = "," + m.sval;  // entries are comma-separated: match whole names
      const auto at = list.find("," + name + "=");
      if (at == std::string::npos) continue;
      const std::string entry = list.substr(at, list.find('&', at) - at);
      if ((entry + ":").find("=" + last_var + ":") != std::string::npos ||
          (entry + ":").find(":" + last_var + ":") != std::string::npos)
        return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

class CliWithServer : public ::testing::Test {
 protected:
  void SetUp() override {
    server.emplace(MOOSDB_LITE_PATH);
    ASSERT_TRUE(server->ok());
    port_arg = "--port=" + std::to_string(server->port());
  }
  void TearDown() override {
    if (server) server->stop();
  }
  std::optional<MoosdbServer> server;
  std::string port_arg;
};

TEST_F(CliWithServer, WatchPrintsWhatPokePostsAsAlogLines) {
  auto watch = Child::spawn(MOOS_CLI_PATH, {"watch", "--host=127.0.0.1", port_arg, "--name=watcher",
                                            "--count=4", "--timeout=15", "NUM", "TXT_*", "BIN"});
  ASSERT_TRUE(watch.has_value());
  ASSERT_TRUE(wait_for_subscriber(server->port(), "watcher", "BIN"));
  const RunResult poke = run_cli({"poke", "--host=127.0.0.1", port_arg, "--name=poker", "NUM=12.5",
                                  "TXT_A=hello world", "TXT_B=\"42\"", "NUM:=not a number"});
  EXPECT_EQ(poke.exit_code, 0) << poke.err;
  EXPECT_EQ(poke.out,
            "NUM = 12.5\nTXT_A = \"hello world\"\nTXT_B = \"42\"\nNUM = \"not a number\"\n");
  // The fourth message: a binary value from our own client.
  TcpClient bin(local_client_options(server->port(), "binposter"));
  ASSERT_TRUE(bin.start() && bin.wait_until_connected(5.0));
  ASSERT_TRUE(bin.notify_binary("BIN", std::string("\x00\xff\x10\x7f", 4)));
  ASSERT_TRUE(bin.flush(5.0));

  const auto rc = watch->wait(kRun_s);
  EXPECT_EQ(rc, 0) << watch->stderr_text();
  const auto lines = alog_entries(watch->stdout_text());
  ASSERT_EQ(lines.size(), 4u) << watch->stdout_text();
  EXPECT_EQ(lines[0].variable, "NUM");
  EXPECT_EQ(lines[0].source, "poker");
  EXPECT_EQ(lines[0].value, "12.5");
  EXPECT_EQ(lines[1].value, "hello world");
  EXPECT_EQ(lines[2].variable, "TXT_B");
  EXPECT_EQ(lines[2].value, "42");  // the string type won: NUM stays double, its string is dropped
  EXPECT_EQ(lines[3].variable, "BIN");
  EXPECT_EQ(lines[3].value, "<binary:4:00ff107f>");
  EXPECT_GE(lines[0].time_s, 0.0);
}

TEST_F(CliWithServer, WatchTimesOutWithExitTwoWhenTheCountIsNotReached) {
  const RunResult watch = run_cli({"watch", port_arg, "--count=1", "--timeout=0.5", "NOTHING_HERE"});
  EXPECT_EQ(watch.exit_code, 2);
  EXPECT_NE(watch.err.find("timed out"), std::string::npos);
}

TEST_F(CliWithServer, WatchWithoutCountEndsNormallyAtTheTimeout) {
  const RunResult watch = run_cli({"watch", port_arg, "--timeout=0.5", "NOTHING_HERE"});
  EXPECT_EQ(watch.exit_code, 0) << watch.err;
}

TEST_F(CliWithServer, DuplicateNameIsRefusedWithExitFour) {
  TcpClient holder(local_client_options(server->port(), "taken"));
  ASSERT_TRUE(holder.start() && holder.wait_until_connected(5.0));
  const RunResult poke = run_cli({"poke", port_arg, "--name=taken", "X=1"});
  EXPECT_EQ(poke.exit_code, 4);
  EXPECT_NE(poke.err.find("taken"), std::string::npos);
}

TEST(CliWithoutServer, NoServerMeansExitThree) {
  int port = 0;
  {
    MoosdbServer s(MOOSDB_LITE_PATH);
    ASSERT_TRUE(s.ok());
    port = s.port();
    s.stop();
  }
  const RunResult poke =
      run_cli({"poke", "--port=" + std::to_string(port), "--connect-timeout=0.5", "X=1"});
  EXPECT_EQ(poke.exit_code, 3);
  EXPECT_NE(poke.err.find("no connection"), std::string::npos);
}

TEST(CliWithoutServer, AHostThatDoesNotResolveMeansExitThreeNamingIt) {
  const RunResult poke = run_cli(
      {"poke", "--host=no-such-host.invalid", "--connect-timeout=0.5", "X=1"});
  EXPECT_EQ(poke.exit_code, 3);
  EXPECT_NE(poke.err.find("no connection to no-such-host.invalid:9000"), std::string::npos)
      << poke.err;
  EXPECT_NE(poke.err.find("cannot resolve host no-such-host.invalid"), std::string::npos)
      << poke.err;
}

// The longest wait allowed still waits: its deadline does not overflow.
TEST_F(CliWithServer, TheLongestTimeoutsStillWaitForTheMessage_Hardening) {
  auto watch = Child::spawn(MOOS_CLI_PATH, {"watch", port_arg, "--name=patient", "--count=1",
                                            "--timeout=1e8", "--connect-timeout=1e8", "LATE"});
  ASSERT_TRUE(watch.has_value());
  ASSERT_TRUE(wait_for_subscriber(server->port(), "patient", "LATE"));
  const RunResult poke = run_cli({"poke", port_arg, "--connect-timeout=1e8", "LATE=1"});
  EXPECT_EQ(poke.exit_code, 0) << poke.err;
  EXPECT_EQ(watch->wait(kRun_s), 0) << watch->stderr_text();
  EXPECT_EQ(alog_entries(watch->stdout_text()).size(), 1u);
}

TEST(CliUsage, BadUsageExitsOneAndHelpExitsZero) {
  const RunResult bad = run_cli({"poke"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("poke needs at least one VAR=value"), std::string::npos);
  const RunResult help = run_cli({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("moos-cli watch"), std::string::npos);
}

}  // namespace
}  // namespace moos
