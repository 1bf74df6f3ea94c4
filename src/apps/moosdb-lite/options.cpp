// Command line and mission globals of moosdb-lite. See options.hpp.

#include "options.hpp"

#include <arpa/inet.h>

#include <cmath>
#include <limits>

#include "hub.hpp"
#include "moos/codec.hpp"
#include "moos/limits.hpp"
#include "moos/message.hpp"
#include "base/text.hpp"

namespace moosdb_lite {

namespace {

/// The smallest packet that can hold one message: below this no client could talk.
constexpr std::size_t kMinPacketLimitBytes = moos::kPacketHeaderSize + moos::Message::kFixedEncodedSize;

// Switches of the reference MOOSDB (spec 5.11) that moosdb-lite accepts and ignores.
struct IgnoredSwitch {
  std::string_view name;      ///< without any "=value"
  std::string_view why;
};
const std::vector<IgnoredSwitch>& ignored_switches() {
  static const std::vector<IgnoredSwitch> table = {
      {"--response", "per-client response delays are not implemented"},
      {"-s", "moosdb-lite has one mode (single thread, asynchronous clients supported)"},
      {"--single_threaded", "moosdb-lite has one mode (single thread, asynchronous clients supported)"},
      {"-d", "no DNS lookups are made"},
      {"--dns", "no DNS lookups are made"},
      {"--tcpnodelay", "TCP_NODELAY is always set"},
      {"--audit_port", "the UDP audit port is not implemented"},
      {"--event_log", "the event log is not implemented; see --log"},
      {"--webserver_port", "the web server is not implemented"},
  };
  return table;
}

// Mission globals of the reference MOOSDB that moosdb-lite ignores (spec 5.11).
const std::vector<IgnoredSwitch>& ignored_globals() {
  static const std::vector<IgnoredSwitch> table = {
      {"WarningLatency", "latency warnings are not implemented"},
      {"WebServerPort", "the web server is not implemented"},
      {"NoNetwork", "moosdb-lite always listens on TCP"},
      {"tcpnodelay", "TCP_NODELAY is always set"},
  };
  return table;
}

std::optional<int> parse_port(std::string_view text) {
  const auto value = base::parse_number(text);
  if (!value || *value != std::floor(*value) || *value < 0 || *value > moos::kMaxPort)
    return std::nullopt;
  return static_cast<int>(*value);
}

std::optional<double> parse_non_negative(std::string_view text) {
  const auto value = base::parse_number(text);
  if (!value || *value < 0.0) return std::nullopt;
  return value;
}

std::optional<double> parse_positive(std::string_view text) {
  const auto value = base::parse_number(text);
  if (!value || *value <= 0.0) return std::nullopt;
  return value;
}

std::optional<std::size_t> parse_byte_count(std::string_view text, std::size_t minimum) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
    return std::nullopt;
  if (text.size() > std::numeric_limits<std::size_t>::digits10) return std::nullopt;
  const std::size_t value = std::stoull(std::string(text));
  if (value < minimum) return std::nullopt;
  return value;
}

bool is_ipv4_literal(const std::string& text) {
  in_addr addr{};
  return inet_pton(AF_INET, text.c_str(), &addr) == 1;
}

// Parses `--name=value` switches with a typed setter each.
template <typename T, typename Parser>
void set_from(std::optional<T>& field, std::string_view arg, std::string_view value,
              Parser parse, std::string_view expected, std::vector<std::string>& errors) {
  const auto parsed = parse(value);
  if (!parsed) {
    errors.push_back(std::string(arg) + ": " + std::string(expected));
    return;
  }
  field = *parsed;
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
      {"--banner-timeout=S", "seconds a new connection has to send the protocol banner (default " +
                                 base::format_g(kDefaultBannerTimeout_s) + ")"},
      {"--handshake-timeout=S", "seconds to send the identification after the banner (default " +
                                    base::format_g(kDefaultHandshakeTimeout_s) + ")"},
      {"--help, -h", "print this help and exit"},
      {"--version", "print the version and exit"},
      {"--response= -s --single_threaded -d --dns --tcpnodelay --audit_port= --event_log= "
       "--webserver_port=",
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

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cli;
  auto& errors = cli.errors;
  for (const std::string& arg : args) {
    const auto eq = arg.find('=');
    const std::string_view name = std::string_view(arg).substr(0, eq);
    const std::string_view value =
        eq == std::string::npos ? std::string_view() : std::string_view(arg).substr(eq + 1);
    const bool has_value = eq != std::string::npos;
    auto want_value = [&]() {
      if (!has_value) errors.push_back(arg + ": expected " + std::string(name) + "=VALUE");
      return has_value;
    };
    auto text = [](std::string_view v) -> std::optional<std::string> {
      if (v.empty()) return std::nullopt;
      return std::string(v);
    };

    if (arg == "--help" || arg == "-h") {
      cli.help = true;
    } else if (arg == "--version") {
      cli.version = true;
    } else if (name == "--moos_port") {
      if (want_value()) set_from(cli.port, arg, value, parse_port, "not a port number (0-65535)", errors);
    } else if (name == "--moos_community") {
      if (want_value()) set_from(cli.community, arg, value, text, "empty community name", errors);
    } else if (name == "--moos_time_warp") {
      if (want_value()) set_from(cli.time_warp, arg, value, moos::parse_time_warp, "time warp must be a number in (0, 400]", errors);
    } else if (name == "--moos_timeout") {
      if (want_value()) set_from(cli.client_timeout_s, arg, value, parse_non_negative, "timeout must be a number of seconds >= 0", errors);
    } else if (name == "--bind") {
      if (want_value()) {
        set_from(cli.bind_address, arg, value,
                 [](std::string_view v) -> std::optional<std::string> {
                   if (!is_ipv4_literal(std::string(v))) return std::nullopt;
                   return std::string(v);
                 },
                 "not an IPv4 address (libMOOS clients connect over IPv4 only)", errors);
      }
    } else if (name == "--port-file") {
      if (want_value()) set_from(cli.port_file, arg, value, text, "empty file name", errors);
    } else if (name == "--log") {
      if (want_value()) set_from(cli.log_file, arg, value, text, "empty file name", errors);
    } else if (name == "--max-packet-bytes") {
      if (want_value())
        set_from(cli.max_packet_bytes, arg, value,
                 [](std::string_view v) { return parse_byte_count(v, kMinPacketLimitBytes); },
                 "expected a whole number of bytes >= " + std::to_string(kMinPacketLimitBytes), errors);
    } else if (name == "--max-output-bytes") {
      if (want_value())
        set_from(cli.max_output_bytes, arg, value,
                 [](std::string_view v) { return parse_byte_count(v, kMinPacketLimitBytes); },
                 "expected a whole number of bytes >= " + std::to_string(kMinPacketLimitBytes), errors);
    } else if (name == "--banner-timeout") {
      if (want_value()) set_from(cli.banner_timeout_s, arg, value, parse_positive, "expected seconds > 0", errors);
    } else if (name == "--handshake-timeout") {
      if (want_value()) set_from(cli.handshake_timeout_s, arg, value, parse_positive, "expected seconds > 0", errors);
    } else if (!arg.empty() && arg[0] == '-') {
      bool known = false;
      for (const auto& ignored : ignored_switches()) {
        if (name == ignored.name) {
          cli.notes.push_back(arg + " ignored: " + std::string(ignored.why));
          known = true;
        }
      }
      if (!known) errors.push_back(arg + ": unknown option (try --help)");
    } else if (!cli.mission_file) {
      cli.mission_file = arg;
    } else if (!cli.alias) {
      cli.alias = arg;  // pAntler passes `<mission> <alias>`; the DB has no use for it
    } else {
      errors.push_back(arg + ": unexpected extra argument");
    }
  }
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
    if (auto v = mission_global("ServerPort")) {
      if (auto port = parse_port(*v)) options.port = *port;
      else bad("ServerPort", *v, "not a port number (0-65535)");
    }
    if (auto v = mission_global("MOOSTimeWarp")) {
      if (auto warp = moos::parse_time_warp(*v)) options.time_warp = *warp;
      else bad("MOOSTimeWarp", *v, "time warp must be a number in (0, 400]");
    }
    if (auto v = mission_global("ClientTimeout")) {
      if (auto timeout = parse_non_negative(*v)) options.client_timeout_s = *timeout;
      else bad("ClientTimeout", *v, "timeout must be a number of seconds >= 0");
    }
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
  if (cli.banner_timeout_s) options.banner_timeout_s = *cli.banner_timeout_s;
  if (cli.handshake_timeout_s) options.handshake_timeout_s = *cli.handshake_timeout_s;
  // ClientTimeout 0 means "never" (spec 1.9 has no such value; we say it explicitly).
  if (options.client_timeout_s && *options.client_timeout_s == 0.0)
    options.client_timeout_s.reset();
  return options;
}

}  // namespace moosdb_lite
