// moos-cli as a process against moosdb-lite: poke and watch, their output and exit codes
// (documented in src/apps/moos-cli/MoosCli_Info.cpp).
#include <gtest/gtest.h>

#include <thread>

#include "moos/alog.hpp"
#include "moos/tcp_client.hpp"
#include "process_support.hpp"

namespace moos {
namespace {

using process_test::Child;
using process_test::run_cli;
using process_test::Server;
using process_test::steady_now_s;

constexpr double kRun_s = 20.0;  // bound on any single moos-cli run

std::vector<AlogEntry> parse_lines(const std::string& text) {
  std::vector<AlogEntry> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const auto line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    const auto parsed = parse_alog_line(line);
    if (parsed.kind == AlogLineKind::kEntry) out.push_back(parsed.entry);
    if (nl == std::string::npos) break;
    pos = nl + 1;
  }
  return out;
}

/// Waits until moos-cli watch has subscribed (its client name appears in DB_CLIENTS).
bool wait_for_client(int port, const std::string& name) {
  TcpClientOptions o;
  o.host = "127.0.0.1";
  o.port = port;
  o.name = "probe_" + name;
  TcpClient probe(o);
  if (!probe.start() || !probe.wait_until_connected(5.0)) return false;
  probe.register_variable("DB_CLIENTS");
  const double deadline = steady_now_s() + 10.0;
  while (steady_now_s() < deadline) {
    probe.notify("PROBE_TICK", 1.0);  // DB variables refresh on traffic in the reference DB
    for (const auto& m : probe.fetch())
      if (m.key == "DB_CLIENTS" && m.sval.find(name + ",") != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

class CliWithServer : public ::testing::Test {
 protected:
  void SetUp() override {
    server = Server::start();
    ASSERT_TRUE(server.has_value());
    port_arg = "--port=" + std::to_string(server->port());
  }
  void TearDown() override {
    if (server) server->process().stop();
  }
  std::optional<Server> server;
  std::string port_arg;
};

TEST_F(CliWithServer, WatchPrintsWhatPokePostsAsAlogLines) {
  auto watch = Child::spawn(MOOS_CLI_PATH, {"watch", "--host=127.0.0.1", port_arg, "--name=watcher",
                                            "--count=4", "--timeout=15", "NUM", "TXT_*", "BIN"});
  ASSERT_TRUE(watch.has_value());
  ASSERT_TRUE(wait_for_client(server->port(), "watcher"));
  std::optional<int> poke_rc;
  Child poke = run_cli({"poke", "--host=127.0.0.1", port_arg, "--name=poker", "NUM=12.5",
                        "TXT_A=hello world", "TXT_B=\"42\"", "NUM:=not a number"},
                       kRun_s, &poke_rc);
  EXPECT_EQ(poke_rc, 0) << poke.stderr_text();
  EXPECT_EQ(poke.stdout_text(),
            "NUM = 12.5\nTXT_A = \"hello world\"\nTXT_B = \"42\"\nNUM = \"not a number\"\n");
  // The fourth message: a binary value from our own client.
  TcpClientOptions o;
  o.host = "127.0.0.1";
  o.port = server->port();
  o.name = "binposter";
  TcpClient bin(o);
  ASSERT_TRUE(bin.start() && bin.wait_until_connected(5.0));
  ASSERT_TRUE(bin.notify_binary("BIN", std::string("\x00\xff\x10\x7f", 4)));
  ASSERT_TRUE(bin.flush(5.0));

  const auto rc = watch->wait(kRun_s);
  EXPECT_EQ(rc, 0) << watch->stderr_text();
  const auto lines = parse_lines(watch->stdout_text());
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
  std::optional<int> rc;
  Child watch = run_cli({"watch", port_arg, "--count=1", "--timeout=0.5", "NOTHING_HERE"}, kRun_s, &rc);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(watch.stderr_text().find("timed out"), std::string::npos);
}

TEST_F(CliWithServer, WatchWithoutCountEndsNormallyAtTheTimeout) {
  std::optional<int> rc;
  Child watch = run_cli({"watch", port_arg, "--timeout=0.5", "NOTHING_HERE"}, kRun_s, &rc);
  EXPECT_EQ(rc, 0) << watch.stderr_text();
}

TEST_F(CliWithServer, DuplicateNameIsRefusedWithExitFour) {
  TcpClientOptions o;
  o.host = "127.0.0.1";
  o.port = server->port();
  o.name = "taken";
  TcpClient holder(o);
  ASSERT_TRUE(holder.start() && holder.wait_until_connected(5.0));
  std::optional<int> rc;
  Child poke = run_cli({"poke", port_arg, "--name=taken", "X=1"}, kRun_s, &rc);
  EXPECT_EQ(rc, 4);
  EXPECT_NE(poke.stderr_text().find("taken"), std::string::npos);
}

TEST(CliWithoutServer, NoServerMeansExitThree) {
  int port = 0;
  {
    auto s = Server::start();
    ASSERT_TRUE(s.has_value());
    port = s->port();
    s->process().stop();
  }
  std::optional<int> rc;
  Child poke = run_cli({"poke", "--port=" + std::to_string(port), "--connect-timeout=0.5", "X=1"},
                       kRun_s, &rc);
  EXPECT_EQ(rc, 3);
  EXPECT_NE(poke.stderr_text().find("no connection"), std::string::npos);
}

TEST(CliUsage, BadUsageExitsOneAndHelpExitsZero) {
  std::optional<int> rc;
  Child bad = run_cli({"poke"}, kRun_s, &rc);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(bad.stderr_text().find("poke needs at least one VAR=value"), std::string::npos);
  Child help = run_cli({"--help"}, kRun_s, &rc);
  EXPECT_EQ(rc, 0);
  EXPECT_NE(help.stdout_text().find("moos-cli watch"), std::string::npos);
}

}  // namespace
}  // namespace moos
