#pragma once
// Command-line conventions shared by every MOOS program we build (wire spec 6.4, hazard spec 2).
//
// Contract:
// - Mission file: the first argument ending in `.moos` or `.moos++`; else the first free
//   argument (one that does not start with '-'); `--moos_file=F` overrides both.
// - Run alias (pAntler launches `<binary> <mission> <alias>`): the second free argument unless it
//   is the mission file; `--alias=NAME` overrides it.
// - Generic switches `--moos_<name>=value` are collected in `moos_switches`; the ones that matter
//   are validated into typed fields (a bad value is an error naming the switch and value, and
//   the field stays unset). `--moos_app_name NAME` and `--moos_comms_tick N` take the NEXT
//   argument, as libMOOS reads them.
// - Every other `--NAME=value` is a substitution for `$(NAME)` in the mission file (nsplug
//   style) AND is listed in `unhandled`, in order, so an application can recognise its own
//   `--name=value` flags. Arguments that start with '-' and carry no '=' (`--help`, `-e`) are
//   listed in `unhandled` too. The parser never prints and never exits: main decides.
// - Information switches (the MOOS-IvP convention, hazard spec 2): -e/--example/-example,
//   -h/--help/-help, -i/--interface (no one-dash -interface), -v/--version/-version, compared as
//   whole words. first_information_switch reads `unhandled` left to right, so the first one on
//   the command line decides.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace moos {

struct CommandLine {
  std::string program;                      ///< argv[0]
  std::optional<std::string> mission_file;
  std::optional<std::string> run_alias;     ///< from --alias= or the second free argument
  /// Free arguments other than the mission file and the alias, in order.
  std::vector<std::string> extra_arguments;
  /// `$(NAME)` values from `--NAME=value`.
  std::map<std::string, std::string> substitutions;
  /// Arguments the generic parser did not consume, in order (app flags, `--NAME=value`).
  std::vector<std::string> unhandled;
  /// Every `--moos_x=value` switch as written (name without the leading dashes); flags without
  /// a value map to "".
  std::map<std::string, std::string> moos_switches;

  // Validated generic switches (unset when absent or invalid).
  std::optional<std::string> moos_name;       ///< --moos_name: the registration (client) name
  std::optional<std::string> moos_app_name;   ///< --moos_app_name NAME
  std::optional<std::string> moos_host;       ///< --moos_host
  std::optional<int> moos_port;               ///< --moos_port, 1..65535
  std::optional<double> moos_time_warp;       ///< --moos_time_warp, 0 < W <= 400 (spec 0.3)
  std::optional<double> moos_app_tick_hz;     ///< --moos_app_tick, > 0 (MOOS-time Hz)
  std::optional<int> moos_comms_tick_hz;      ///< --moos_comms_tick N, 1..200 (spec 4.2)
  std::optional<std::string> moos_community;  ///< --moos_community (servers)
  std::optional<double> moos_timeout_s;       ///< --moos_timeout (servers), > 0

  /// Problems such as `--moos_port=abc`, each naming the argument.
  std::vector<std::string> errors;

  /// True if `flag` (e.g. "--help") or any of `aliases` appears in `unhandled` as a whole word.
  bool has_flag(const std::string& flag, const std::vector<std::string>& aliases = {}) const;
  /// The value of `--name=value` in `unhandled` (last one wins), if present.
  std::optional<std::string> flag_value(const std::string& name) const;
};

/// Parses argv (argv[0] is the program). Never fails; problems go to `errors`.
CommandLine parse_command_line(int argc, const char* const* argv);
CommandLine parse_command_line(const std::vector<std::string>& args);

/// The run name: the alias if one was given, else `default_name` (spec 6.4).
std::string app_name_from(const CommandLine& cl, const std::string& default_name);

/// What an information switch asks main to print (and then exit 0).
enum class InfoSwitch { kExample, kHelp, kInterface, kVersion };

/// The information switch `arg` is, if any (see the contract).
std::optional<InfoSwitch> information_switch(std::string_view arg);

/// The first information switch of the command line, if any.
std::optional<InfoSwitch> first_information_switch(const CommandLine& command_line);

/// What main does with a MOOS-IvP app's command line. kUsageError is for an app's own checks of
/// its own switches (decide_launch never returns it).
enum class LaunchAction { kRun, kHelp, kExample, kInterface, kVersion, kUsageError };

/// The first information switch decides; without one and without a mission file, the help (the
/// MOOS-IvP apps' behaviour); else run.
LaunchAction decide_launch(const CommandLine& command_line);

}  // namespace moos
