#pragma once
// moosdb-lite's configuration: the reference MOOSDB's command line and mission globals
// (docs/protocol.md 5.11) plus our own switches, in one table
// (the parser and --help read the same rows).
//
// Contract:
// - parse_command_line() reads the arguments with libmoos's switch table parser
//   (moos::parse_switches, switch_table()); it never exits and never prints: it returns what it
//   understood, the errors (each naming the argument and why) and notes (real-MOOSDB switches
//   we accept and ignore). A port is one the server can listen on (moos::kListenPortRange: 0
//   lets the OS pick), a whole number.
// - The mission globals obey the rules of the switches that override them (ServerPort:
//   --moos_port, MOOSTimeWarp: --moos_time_warp, ClientTimeout: --moos_timeout, 0 = never).
// - resolve_options() merges, in increasing priority: built-in defaults, mission globals
//   (Community, ServerPort, MOOSTimeWarp, ClientTimeout), command-line switches. Every bad
//   value is an error naming where it came from (switch, or mission file and variable).
// - The first free argument is the mission file, the second the pAntler alias (ignored).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/command_line.hpp"

namespace moosdb_lite {

/// Defaults of the reference MOOSDB (protocol.md 5.11, 1.1) and our own.
inline constexpr int kDefaultPort = 9000;
inline constexpr const char* kDefaultBindAddress = "127.0.0.1";
inline constexpr const char* kDefaultMissionFile = "Mission.moos";

/// One row of the option table: what --help prints.
struct OptionDoc {
  std::string name;     ///< e.g. "--moos_port=PORT"
  std::string meaning;  ///< one line, with the default (built from the constants)
};
const std::vector<OptionDoc>& option_docs();
/// Mission-file globals that moosdb-lite reads, with meaning and default.
const std::vector<OptionDoc>& mission_global_docs();

/// The switches of moosdb-lite, with the reference MOOSDB's that it accepts and ignores.
const moos::SwitchTable& switch_table();

/// What the command line says; unset fields were not given.
struct CommandLine {
  std::optional<std::string> mission_file;
  std::optional<std::string> alias;
  std::optional<std::string> community;
  std::optional<int> port;
  std::optional<double> time_warp;
  std::optional<double> client_timeout_s;
  std::optional<std::string> bind_address;
  std::optional<std::string> log_file;
  std::optional<std::string> port_file;
  std::optional<std::size_t> max_packet_bytes;
  std::optional<std::size_t> max_output_bytes;
  std::optional<std::size_t> memory_budget_bytes;
  std::optional<std::size_t> max_stored_bytes;
  std::optional<double> banner_timeout_s;
  std::optional<double> handshake_timeout_s;
  bool help = false;
  bool version = false;
  std::vector<std::string> notes;
  std::vector<std::string> errors;
};

CommandLine parse_command_line(const std::vector<std::string>& args);

/// The resolved configuration of one server run.
struct ServerOptions {
  std::optional<std::string> mission_file;  ///< the file actually read, if any
  std::string community;
  int port = kDefaultPort;                  ///< 0: the OS picks a free port
  double time_warp = 1.0;
  std::optional<double> client_timeout_s;   ///< nullopt: clients never time out
  std::string bind_address = kDefaultBindAddress;
  std::optional<std::string> log_file;
  std::optional<std::string> port_file;
  std::size_t max_packet_bytes = 0;
  std::size_t max_output_bytes = 0;
  std::size_t memory_budget_bytes = 0;  ///< over every client's unsent output and partial packets
  std::size_t max_stored_bytes = 0;     ///< the variables' names and last values
  double banner_timeout_s = 0.0;
  double handshake_timeout_s = 0.0;
};

/// Looks a mission global up (case-insensitive key, blanks removed from the value);
/// nullopt if absent. An empty function means "no mission file".
using MissionGlobalLookup = std::function<std::optional<std::string>(std::string_view key)>;

/// Merges defaults, mission globals and the command line (see the contract). `mission_name`
/// names the mission file in errors. Problems go to `errors`, ignored settings to `notes`.
ServerOptions resolve_options(const CommandLine& cli, const std::string& mission_name,
                              const MissionGlobalLookup& mission_global,
                              std::vector<std::string>* errors, std::vector<std::string>* notes);

}  // namespace moosdb_lite
