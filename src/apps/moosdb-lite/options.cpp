// Command line and mission globals of moosdb-lite. See options.hpp.

#include "options.hpp"

#include <arpa/inet.h>

#include <stdexcept>

#include "event_loop.hpp"
#include "hub.hpp"
#include "moos/codec.hpp"
#include "moos/limits.hpp"
#include "moos/message.hpp"
#include "base/text.hpp"

namespace moosdb_lite {

namespace {

/// The smallest packet that can hold one message: below this no client could talk.
constexpr std::size_t kMinPacketLimitBytes = moos::kPacketHeaderSize + moos::Message::kFixedEncodedSize;

/// Reasons shared by several rows.
constexpr const char* kEmptyFileName = "empty file name";
constexpr const char* kOneMode =
    "moosdb-lite has one mode (single thread, asynchronous clients supported)";
constexpr const char* kNoDns = "no DNS lookups are made";
constexpr const char* kNoWebServer = "the web server is not implemented";
constexpr const char* kNoDelay = "TCP_NODELAY is always set";
constexpr const char* kNoSuicide = "suicide monitoring is not implemented (stop moosdb-lite with a signal)";
constexpr const char* kNoBoost = "moosdb-lite runs at normal priority";
/// Seconds of silence before a client is dropped: 0 means never (ClientTimeout, --moos_timeout).
constexpr moos::Range kClientTimeoutRange_s = moos::kNonNegative;

bool is_ipv4_literal(const std::string& text) {
  in_addr addr{};
  return inet_pton(AF_INET, text.c_str(), &addr) == 1;
}

// The reference MOOSDB prints its version with --moos_print_version (MOOSDB --help).
moos::SwitchRule version_row() {
  moos::SwitchRule r = moos::switch_rule("--version", moos::SwitchKind::kFlag, "");
  r.aliases = {"--moos_print_version"};
  return r;
}

moos::SwitchRule bind_row() {
  moos::SwitchRule r = moos::switch_rule("--bind", moos::SwitchKind::kText,
                                         "not an IPv4 address (libMOOS clients connect over IPv4 only)");
  r.check = is_ipv4_literal;
  return r;
}

const moos::SwitchRule& rule_named(const std::string& name) {
  for (const moos::SwitchRule& r : switch_table().rules)
    if (r.name == name) return r;
  throw std::logic_error("moosdb-lite has no switch " + name);  // a typo in this file
}

// Mission globals of the reference MOOSDB that moosdb-lite ignores (protocol.md 5.11).
struct IgnoredGlobal {
  std::string_view name;
  std::string_view why;
};
const std::vector<IgnoredGlobal>& ignored_globals() {
  static const std::vector<IgnoredGlobal> table = {
      {"WarningLatency", "latency warnings are not implemented"},
      {"WebServerPort", kNoWebServer},
      {"NoNetwork", "moosdb-lite always listens on TCP"},
      {"tcpnodelay", kNoDelay},
  };
  return table;
}

template <typename T>
std::optional<T> optional_cast(const std::optional<long long>& v) {
  if (!v) return std::nullopt;
  return static_cast<T>(*v);
}

}  // namespace

const std::vector<OptionDoc>& option_docs() {
  static const std::vector<OptionDoc> table = {
      {"MISSION [ALIAS]", std::string("mission file (default ") + kDefaultMissionFile +
                              " if it exists); the pAntler alias is ignored"},
      {"--moos_port=PORT", "TCP port (default: ServerPort, else " + std::to_string(kDefaultPort) +
                               "); 0 lets the OS pick a free port"},
      {"--moos_community=NAME",
       std::string("community name (default: Community, else ") + kDefaultCommunity + ")"},
      {"--moos_time_warp=W", "time warp, 0 < W <= " + base::format_g(moos::kMaxTimeWarp) +
                                 " (default: MOOSTimeWarp, else 1)"},
      {"--moos_timeout=S", "drop a client silent for S seconds (default: ClientTimeout, else " +
                               base::format_g(kDefaultClientTimeout_s) + "; 0 = never)"},
      {"--bind=ADDR", std::string("IPv4 address to listen on (default ") + kDefaultBindAddress +
                          "; 0.0.0.0 = every interface)"},
      {"--port-file=FILE", "write the bound port number to FILE once listening"},
      {"--log=FILE", "write every accepted NOTIFY to FILE in pLogger's .alog format"},
      {"--max-packet-bytes=N", "largest packet accepted from a client (default " +
                                   std::to_string(kDefaultServerMaxPacketBytes) + ")"},
      {"--max-output-bytes=N", "unsent bytes allowed per client before it is dropped (default " +
                                   std::to_string(kDefaultMaxPendingBytes) + ")"},
      {"--memory-budget-bytes=N", "bytes all clients together may hold in the server (unsent "
                                  "output, partial packets) before the largest holder is dropped "
                                  "(default " + std::to_string(kDefaultMemoryBudgetBytes) + ")"},
      {"--max-stored-bytes=N", "bytes the stored variables (names, last values) may hold; a "
                               "write or registration beyond is refused (default " +
                                   std::to_string(kDefaultMaxStoredBytes) + ")"},
      {"--banner-timeout=S", "seconds a new connection has to send the protocol banner (default " +
                                 base::format_g(kDefaultBannerTimeout_s) + ")"},
      {"--handshake-timeout=S", "seconds to send the identification after the banner (default " +
                                    base::format_g(kDefaultHandshakeTimeout_s) + ")"},
      {"--moos_file=FILE", "mission file, as the first free argument"},
      {"--help, -h", "print this help and exit"},
      {"--version, --moos_print_version", "print the version and exit"},
      {"--response= -s --single_threaded -d --dns -b --moos_boost --tcpnodelay --audit_port= "
       "--event_log= --webserver_port= --warning_latency= --print_heart_beat --moos_no_colour "
       "--moos_suicide_channel= --moos_suicide_port= --moos_suicide_phrase= "
       "--moos_suicide_disable --moos_suicide_print",
       "reference MOOSDB switches: accepted and ignored, with a note"},
  };
  return table;
}

const std::vector<OptionDoc>& mission_global_docs() {
  static const std::vector<OptionDoc> table = {
      {"Community", std::string("community name (default ") + kDefaultCommunity + ")"},
      {"ServerPort", "TCP port (default " + std::to_string(kDefaultPort) + ")"},
      {"MOOSTimeWarp", "time warp (default 1)"},
      {"ClientTimeout", "seconds of silence before a client is dropped (default " +
                            base::format_g(kDefaultClientTimeout_s) + "; 0 = never)"},
  };
  return table;
}

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  using moos::switch_rule;
  static const moos::SwitchTable table = [] {
    const std::string bytes =
        "expected a whole number of bytes >= " + std::to_string(kMinPacketLimitBytes);
    const moos::Range byte_range{double(kMinPacketLimitBytes), moos::kAnyNumber.high};
    moos::SwitchTable t;
    t.rules = {
        switch_rule("--moos_port", SwitchKind::kInteger, "not a port number (0-65535)",
                    moos::kListenPortRange),
        switch_rule("--moos_community", SwitchKind::kText, "empty community name"),
        switch_rule("--moos_time_warp", SwitchKind::kNumber,
                    "time warp must be a number in (0, 400]", moos::kTimeWarpRange),
        switch_rule("--moos_timeout", SwitchKind::kNumber,
                    "timeout must be a number of seconds >= 0", kClientTimeoutRange_s),
        bind_row(),
        switch_rule("--port-file", SwitchKind::kText, kEmptyFileName),
        switch_rule("--log", SwitchKind::kText, kEmptyFileName),
        switch_rule("--max-packet-bytes", SwitchKind::kUnsigned, bytes, byte_range),
        switch_rule("--max-output-bytes", SwitchKind::kUnsigned, bytes, byte_range),
        switch_rule("--memory-budget-bytes", SwitchKind::kUnsigned, bytes, byte_range),
        switch_rule("--max-stored-bytes", SwitchKind::kUnsigned, bytes, byte_range),
        switch_rule("--banner-timeout", SwitchKind::kNumber, "expected seconds > 0",
                    moos::kPositive),
        switch_rule("--handshake-timeout", SwitchKind::kNumber, "expected seconds > 0",
                    moos::kPositive),
        switch_rule("--moos_file", SwitchKind::kText, kEmptyFileName),
        moos::help_switch_rule(),
        version_row(),
        // Switches of the reference MOOSDB (protocol.md 5.11) that moosdb-lite accepts and ignores.
        switch_rule("--response", SwitchKind::kIgnored,
                    "per-client response delays are not implemented"),
        switch_rule("-s", SwitchKind::kIgnored, kOneMode),
        switch_rule("--single_threaded", SwitchKind::kIgnored, kOneMode),
        switch_rule("-d", SwitchKind::kIgnored, kNoDns),
        switch_rule("--dns", SwitchKind::kIgnored, kNoDns),
        switch_rule("--tcpnodelay", SwitchKind::kIgnored, kNoDelay),
        switch_rule("--audit_port", SwitchKind::kIgnored, "the UDP audit port is not implemented"),
        switch_rule("--event_log", SwitchKind::kIgnored,
                    "the event log is not implemented; see --log"),
        switch_rule("--webserver_port", SwitchKind::kIgnored, kNoWebServer),
        switch_rule("-b", SwitchKind::kIgnored, kNoBoost),
        switch_rule("--moos_boost", SwitchKind::kIgnored, kNoBoost),
        switch_rule("--warning_latency", SwitchKind::kIgnored, "latency warnings are not implemented"),
        switch_rule("--print_heart_beat", SwitchKind::kIgnored, "no heartbeat is printed"),
        switch_rule("--moos_no_colour", SwitchKind::kIgnored, "moosdb-lite prints no colour"),
        switch_rule("--moos_suicide_channel", SwitchKind::kIgnored, kNoSuicide),
        switch_rule("--moos_suicide_port", SwitchKind::kIgnored, kNoSuicide),
        switch_rule("--moos_suicide_phrase", SwitchKind::kIgnored, kNoSuicide),
        switch_rule("--moos_suicide_disable", SwitchKind::kIgnored, kNoSuicide),
        switch_rule("--moos_suicide_print", SwitchKind::kIgnored, kNoSuicide),
    };
    t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return arg + ": " + r.problem;
    };
    t.missing_value = [](const std::string& arg, const moos::SwitchRule& r) {
      return arg + ": expected " + r.name + "=VALUE";
    };
    t.unknown = [](const std::string& arg) { return arg + ": unknown option (try --help)"; };
    return t;
  }();
  return table;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  const moos::SwitchValues v = moos::parse_switches(args, switch_table());
  CommandLine cli;
  cli.help = v.has("--help");
  cli.version = v.has("--version");
  cli.port = optional_cast<int>(v.integer("--moos_port"));
  cli.community = v.text("--moos_community");
  cli.time_warp = v.number("--moos_time_warp");
  cli.client_timeout_s = v.number("--moos_timeout");
  cli.bind_address = v.text("--bind");
  cli.port_file = v.text("--port-file");
  cli.log_file = v.text("--log");
  cli.max_packet_bytes = v.whole("--max-packet-bytes");
  cli.max_output_bytes = v.whole("--max-output-bytes");
  cli.memory_budget_bytes = v.whole("--memory-budget-bytes");
  cli.max_stored_bytes = v.whole("--max-stored-bytes");
  cli.banner_timeout_s = v.number("--banner-timeout");
  cli.handshake_timeout_s = v.number("--handshake-timeout");
  cli.notes = v.notes;
  cli.errors = v.errors;
  // pAntler passes `<mission> <alias>`; the DB has no use for the alias. The reference MOOSDB
  // also takes the mission as --moos_file; a free argument wins.
  cli.mission_file = v.text("--moos_file");
  if (!v.free.empty()) cli.mission_file = v.free[0];
  if (v.free.size() > 1) cli.alias = v.free[1];
  for (std::size_t i = 2; i < v.free.size(); ++i)
    cli.errors.push_back(v.free[i] + ": unexpected extra argument");
  return cli;
}

ServerOptions resolve_options(const CommandLine& cli, const std::string& mission_name,
                              const MissionGlobalLookup& mission_global,
                              std::vector<std::string>* errors, std::vector<std::string>* notes) {
  ServerOptions options;
  options.community = kDefaultCommunity;
  options.client_timeout_s = kDefaultClientTimeout_s;
  options.max_packet_bytes = kDefaultServerMaxPacketBytes;
  options.max_output_bytes = kDefaultMaxPendingBytes;
  options.memory_budget_bytes = kDefaultMemoryBudgetBytes;
  options.max_stored_bytes = kDefaultMaxStoredBytes;
  options.banner_timeout_s = kDefaultBannerTimeout_s;
  options.handshake_timeout_s = kDefaultHandshakeTimeout_s;

  if (mission_global) {
    options.mission_file = mission_name;
    auto bad = [&](std::string_view key, const std::string& value, std::string_view expected) {
      errors->push_back(mission_name + ": " + std::string(key) + " = " + value + ": " +
                        std::string(expected));
    };
    if (auto v = mission_global("Community")) {
      if (v->empty()) bad("Community", *v, "empty community name");
      else options.community = *v;
    }
    // The globals obey the rules of the switches that override them.
    auto checked = [&](std::string_view key, const char* switch_name) -> std::optional<std::string> {
      const std::optional<std::string> v = mission_global(key);
      if (!v) return std::nullopt;
      const moos::SwitchRule& rule = rule_named(switch_name);
      if (moos::accepts(rule, *v)) return v;
      bad(key, *v, rule.problem);
      return std::nullopt;
    };
    if (auto v = checked("ServerPort", "--moos_port"))
      options.port = static_cast<int>(base::parse_integer(*v, moos::kAnyListenPort, moos::kMaxPort)
                                          .value_or(kDefaultPort));
    if (auto v = checked("MOOSTimeWarp", "--moos_time_warp")) options.time_warp = *base::parse_number(*v);
    if (auto v = checked("ClientTimeout", "--moos_timeout")) options.client_timeout_s = base::parse_number(*v);
    for (const auto& ignored : ignored_globals()) {
      if (mission_global(ignored.name))
        notes->push_back(mission_name + ": " + std::string(ignored.name) + " ignored: " +
                         std::string(ignored.why));
    }
  }

  if (cli.community) options.community = *cli.community;
  if (cli.port) options.port = *cli.port;
  if (cli.time_warp) options.time_warp = *cli.time_warp;
  if (cli.client_timeout_s) options.client_timeout_s = *cli.client_timeout_s;
  if (cli.bind_address) options.bind_address = *cli.bind_address;
  if (cli.log_file) options.log_file = cli.log_file;
  if (cli.port_file) options.port_file = cli.port_file;
  if (cli.max_packet_bytes) options.max_packet_bytes = *cli.max_packet_bytes;
  if (cli.max_output_bytes) options.max_output_bytes = *cli.max_output_bytes;
  if (cli.memory_budget_bytes) options.memory_budget_bytes = *cli.memory_budget_bytes;
  if (cli.max_stored_bytes) options.max_stored_bytes = *cli.max_stored_bytes;
  if (cli.banner_timeout_s) options.banner_timeout_s = *cli.banner_timeout_s;
  if (cli.handshake_timeout_s) options.handshake_timeout_s = *cli.handshake_timeout_s;
  // ClientTimeout 0 means "never" (protocol.md 1.9 has no such value; we say it explicitly).
  if (options.client_timeout_s && *options.client_timeout_s == 0.0)
    options.client_timeout_s.reset();
  return options;
}

}  // namespace moosdb_lite
