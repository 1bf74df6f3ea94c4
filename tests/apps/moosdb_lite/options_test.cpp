// moosdb-lite's command line and mission globals (protocol.md 5.11) and its help text.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "MoosDBLite_Info.hpp"
#include "doc_tables.hpp"
#include "event_loop.hpp"
#include "hub.hpp"
#include "options.hpp"

namespace moosdb_lite {
namespace {

struct Resolved {
  ServerOptions options;
  std::vector<std::string> errors;
  std::vector<std::string> notes;
};

Resolved resolve(const std::vector<std::string>& args,
                 const std::map<std::string, std::string>* globals = nullptr) {
  const CommandLine cli = parse_command_line(args);
  EXPECT_TRUE(cli.errors.empty()) << cli.errors.front();
  MissionGlobalLookup lookup;
  if (globals) {
    lookup = [globals](std::string_view key) -> std::optional<std::string> {
      const auto it = globals->find(std::string(key));
      if (it == globals->end()) return std::nullopt;
      return it->second;
    };
  }
  Resolved r;
  r.options = resolve_options(cli, "m.moos", lookup, &r.errors, &r.notes);
  return r;
}

TEST(Options, DefaultsAreThoseOfTheReferenceDb_5_11) {
  const auto r = resolve({});
  EXPECT_TRUE(r.errors.empty());
  EXPECT_FALSE(r.options.mission_file);
  EXPECT_EQ(r.options.community, "#1");
  EXPECT_EQ(r.options.port, 9000);
  EXPECT_EQ(r.options.time_warp, 1.0);
  ASSERT_TRUE(r.options.client_timeout_s);
  EXPECT_EQ(*r.options.client_timeout_s, 5.0);
  EXPECT_EQ(r.options.bind_address, "127.0.0.1");
  EXPECT_EQ(r.options.max_packet_bytes, kDefaultServerMaxPacketBytes);
  EXPECT_EQ(r.options.max_packet_bytes, 256u * 1024u * 1024u);  // libMOOS's 2,048 x 100 kB fit
  EXPECT_EQ(r.options.memory_budget_bytes, kDefaultMemoryBudgetBytes);
}

TEST(Options, MissionGlobalsAreRead_5_11) {
  const std::map<std::string, std::string> globals = {
      {"Community", "alpha"}, {"ServerPort", "9100"}, {"MOOSTimeWarp", "10"}, {"ClientTimeout", "8"}};
  const auto r = resolve({"m.moos"}, &globals);
  EXPECT_TRUE(r.errors.empty());
  EXPECT_EQ(r.options.mission_file, "m.moos");
  EXPECT_EQ(r.options.community, "alpha");
  EXPECT_EQ(r.options.port, 9100);
  EXPECT_EQ(r.options.time_warp, 10.0);
  EXPECT_EQ(*r.options.client_timeout_s, 8.0);
}

TEST(Options, CommandLineOverridesMissionGlobals_5_11) {
  const std::map<std::string, std::string> globals = {
      {"Community", "alpha"}, {"ServerPort", "9100"}, {"MOOSTimeWarp", "10"}, {"ClientTimeout", "8"}};
  const auto r = resolve({"m.moos", "pAntlerAlias", "--moos_port=0", "--moos_community=bravo",
                          "--moos_time_warp=2.5", "--moos_timeout=0"},
                         &globals);
  EXPECT_TRUE(r.errors.empty());
  EXPECT_EQ(r.options.community, "bravo");
  EXPECT_EQ(r.options.port, 0);
  EXPECT_EQ(r.options.time_warp, 2.5);
  EXPECT_FALSE(r.options.client_timeout_s);  // 0 = never
}

TEST(Options, BadMissionValuesAreErrorsNamingFileVariableAndValue) {
  const std::map<std::string, std::string> globals = {
      {"ServerPort", "90000"}, {"MOOSTimeWarp", "0"}, {"ClientTimeout", "soon"}};
  const auto r = resolve({"m.moos"}, &globals);
  ASSERT_EQ(r.errors.size(), 3u);
  EXPECT_EQ(r.errors[0], "m.moos: ServerPort = 90000: not a port number (0-65535)");
  EXPECT_EQ(r.errors[1], "m.moos: MOOSTimeWarp = 0: time warp must be a number in (0, 400]");
  EXPECT_EQ(r.errors[2], "m.moos: ClientTimeout = soon: timeout must be a number of seconds >= 0");
}

TEST(Options, IgnoredMissionGlobalsGetANote_5_11) {
  const std::map<std::string, std::string> globals = {{"WebServerPort", "9080"}};
  const auto r = resolve({"m.moos"}, &globals);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], "m.moos: WebServerPort ignored: the web server is not implemented");
}

TEST(Options, OurOwnSwitchesAreParsed) {
  const auto r = resolve({"--bind=0.0.0.0", "--log=run.alog", "--port-file=port.txt",
                          "--max-packet-bytes=4096", "--max-output-bytes=65536",
                          "--banner-timeout=0.5", "--handshake-timeout=0.25"});
  EXPECT_EQ(r.options.bind_address, "0.0.0.0");
  EXPECT_EQ(r.options.log_file, "run.alog");
  EXPECT_EQ(r.options.port_file, "port.txt");
  EXPECT_EQ(r.options.max_packet_bytes, 4096u);
  EXPECT_EQ(r.options.max_output_bytes, 65536u);
  EXPECT_EQ(r.options.banner_timeout_s, 0.5);
  EXPECT_EQ(r.options.handshake_timeout_s, 0.25);
}

TEST(Options, ReferenceDbSwitchesAreAcceptedWithANote_5_11) {
  const CommandLine cli = parse_command_line(
      {"-s", "--single_threaded", "-d", "--dns", "--tcpnodelay", "--response=pA:10",
       "--audit_port=9020", "--event_log=e.txt", "--webserver_port=9080"});
  EXPECT_TRUE(cli.errors.empty());
  ASSERT_EQ(cli.notes.size(), 9u);
  EXPECT_EQ(cli.notes[0].rfind("-s ignored: ", 0), 0u);
  EXPECT_EQ(cli.notes[6], "--audit_port=9020 ignored: the UDP audit port is not implemented");
}

TEST(Options, BadSwitchesAreErrorsNamingTheArgument) {
  const CommandLine cli = parse_command_line(
      {"--moos_port=abc", "--moos_time_warp=401", "--bind=::1", "--frobnicate", "--moos_port",
       "--max-packet-bytes=10", "a.moos", "alias", "third"});
  ASSERT_EQ(cli.errors.size(), 7u);
  EXPECT_EQ(cli.errors[0], "--moos_port=abc: not a port number (0-65535)");
  EXPECT_EQ(cli.errors[1], "--moos_time_warp=401: time warp must be a number in (0, 400]");
  EXPECT_EQ(cli.errors[2], "--bind=::1: not an IPv4 address (libMOOS clients connect over IPv4 only)");
  EXPECT_EQ(cli.errors[3], "--frobnicate: unknown option (try --help)");
  EXPECT_EQ(cli.errors[4], "--moos_port: expected --moos_port=VALUE");
  EXPECT_EQ(cli.errors[5], "--max-packet-bytes=10: expected a whole number of bytes >= 63");
  EXPECT_EQ(cli.errors[6], "third: unexpected extra argument");
  EXPECT_EQ(cli.mission_file, "a.moos");
  EXPECT_EQ(cli.alias, "alias");
}

TEST(Options, EverySwitchOfTheReferenceMoosdbHelpWorksOrIsIgnoredWithANote_Hardening) {
  // MOOSDB --help (core-moos), switch by switch.
  const std::vector<std::string> ignored = {
      "--moos_suicide_channel=127.0.0.1", "--moos_suicide_port=9020", "--moos_suicide_phrase=x",
      "--moos_suicide_disable", "--moos_suicide_print", "--moos_no_colour", "-d", "--dns", "-s",
      "--single_threaded", "-b", "--moos_boost", "--response=x_app:20,*_instrument:0",
      "--warning_latency=50", "--tcpnodelay", "--audit_port=9020", "--event_log=e.txt",
      "--print_heart_beat", "--webserver_port=9080"};
  std::vector<std::string> args = ignored;
  args.insert(args.end(), {"--moos_file=m.moos", "--moos_port=9001", "--moos_time_warp=10",
                           "--moos_community=shore", "--moos_timeout=4"});
  const CommandLine cli = parse_command_line(args);
  EXPECT_EQ(cli.errors, std::vector<std::string>{});
  EXPECT_EQ(cli.notes.size(), ignored.size());
  for (std::size_t i = 0; i < ignored.size() && i < cli.notes.size(); ++i)
    EXPECT_EQ(cli.notes[i].rfind(ignored[i] + " ignored: ", 0), 0u) << cli.notes[i];
  EXPECT_EQ(cli.mission_file, "m.moos");
  EXPECT_EQ(cli.port, 9001);
  EXPECT_EQ(cli.time_warp, 10.0);
  EXPECT_EQ(cli.community, "shore");
  EXPECT_EQ(cli.client_timeout_s, 4.0);
  EXPECT_TRUE(parse_command_line({"--moos_print_version"}).version);
  EXPECT_EQ(parse_command_line({"first.moos", "--moos_file=second.moos"}).mission_file, "first.moos");
}

TEST(Options, HelpAndVersionFlags) {
  EXPECT_TRUE(parse_command_line({"--help"}).help);
  EXPECT_TRUE(parse_command_line({"-h"}).help);
  EXPECT_TRUE(parse_command_line({"--version"}).version);
}

TEST(Info, HelpListsEveryOptionOfTheTable) {
  const std::string help = help_text();
  for (const auto& row : option_docs()) {
    EXPECT_NE(help.find(row.name), std::string::npos) << row.name;
    EXPECT_NE(help.find(row.meaning), std::string::npos) << row.meaning;
  }
  for (const auto& row : mission_global_docs()) EXPECT_NE(help.find(row.name), std::string::npos);
  EXPECT_EQ(version_text().rfind("moosdb-lite ", 0), 0u);
}

TEST(Info, TheDocsSwitchTableIsTheSwitchTable) {
  const auto rows = test_support::doc_table(std::string(HAZARD_SOURCE_DIR) + "/docs/moos.md",
                                            "Command line");
  ASSERT_FALSE(rows.empty()) << "docs/moos.md: no table under '### Command line'";
  EXPECT_EQ(test_support::switches_in_first_column(rows),
            test_support::switches_of(switch_table(), false));
}

TEST(Info, TheDocsMissionGlobalsTableIsTheCodes) {
  const auto rows = test_support::doc_table(std::string(HAZARD_SOURCE_DIR) + "/docs/moos.md",
                                            "Mission globals read");
  ASSERT_FALSE(rows.empty()) << "docs/moos.md: no table under '### Mission globals read'";
  std::vector<std::string> in_doc;
  for (const auto& row : rows) in_doc.push_back(row.front());
  std::vector<std::string> in_code;
  for (const auto& row : mission_global_docs()) in_code.push_back("`" + row.name + "`");
  EXPECT_EQ(in_doc, in_code);
}

TEST(Info, HelpNamesEverySwitchOfTheTable) {
  std::string names;
  for (const auto& row : option_docs()) names += " " + row.name + " ";
  for (const std::string& name : test_support::switches_of(switch_table(), true)) {
    const bool named = names.find(" " + name + "=") != std::string::npos ||
                       names.find(" " + name + " ") != std::string::npos ||
                       names.find(" " + name + ",") != std::string::npos;
    EXPECT_TRUE(named) << name << " is not in option_docs()";
  }
}

TEST(Options, PortsAreWholeNumbersAServerCanListenOn) {
  EXPECT_EQ(parse_command_line({"--moos_port=0"}).port, 0);
  EXPECT_EQ(parse_command_line({"--moos_port=65535"}).port, 65535);
  const CommandLine cli = parse_command_line({"--moos_port=9000.0", "--moos_port=65536"});
  EXPECT_EQ(cli.errors, (std::vector<std::string>{"--moos_port=9000.0: not a port number (0-65535)",
                                                  "--moos_port=65536: not a port number (0-65535)"}));
  const std::map<std::string, std::string> globals = {{"ServerPort", "9000.0"}};
  Resolved r;
  MissionGlobalLookup lookup = [&globals](std::string_view key) -> std::optional<std::string> {
    const auto it = globals.find(std::string(key));
    if (it == globals.end()) return std::nullopt;
    return it->second;
  };
  r.options = resolve_options(parse_command_line({}), "m.moos", lookup, &r.errors, &r.notes);
  EXPECT_EQ(r.errors, (std::vector<std::string>{"m.moos: ServerPort = 9000.0: not a port number (0-65535)"}));
}

}  // namespace
}  // namespace moosdb_lite
