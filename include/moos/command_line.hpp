#pragma once
// Command-line conventions shared by every MOOS program we build (docs/protocol.md 6.4,
// docs/uFldHazardSensor.md),
// and the typed switch table that every program's own switches are read with.
//
// Contract of parse_command_line (the MOOS applications' convention):
// - Mission file: the first argument ending in `.moos` or `.moos++`; else the first free
//   argument (one that does not start with '-'); `--moos_file=F` overrides both.
// - Run alias (pAntler launches `<binary> <mission> <alias>`): the second free argument unless it
//   is the mission file; `--alias=NAME` overrides it.
// - Generic switches `--moos_<name>=value` are collected in `moos_switches`; the ones that matter
//   are validated into typed fields by generic_switch_rules() (a bad value is an error naming
//   the switch and value, and the field stays unset). `--moos_app_name NAME` and
//   `--moos_comms_tick N` take the NEXT argument, as libMOOS reads them.
// - Every other `--NAME=value` is a substitution for `$(NAME)` in the mission file (nsplug
//   style) AND is listed in `unhandled`, in order, so an application can recognise its own
//   `--name=value` flags. Arguments that start with '-' and carry no '=' (`--help`, `-e`) are
//   listed in `unhandled` too. The parser never prints and never exits: main decides.
// - Information switches (the MOOS-IvP convention, docs/uFldHazardSensor.md):
//   -e/--example/-example,
//   -h/--help/-help, -i/--interface (no one-dash -interface), -v/--version/-version, compared as
//   whole words. first_information_switch reads `unhandled` left to right, so the first one on
//   the command line decides.
//
// Contract of parse_switches (a program's own switch table, SwitchRule):
// - An argument that starts with '-' and is longer than "-" is a switch; every other argument is
//   free (kept in order). A switch is looked up by its text before any '=' (its name or an alias).
// - kFlag matches only without '='. kIgnored matches with or without a value and adds the note
//   "<argument> ignored: <problem>". Every other kind needs `=value`: without one, the table's
//   missing_value text (or, when it has none, its unknown text) is an error; a value the rule
//   does not accept (accepts()) gives the table's bad_value text. A switch not in the table
//   gives the table's unknown text.
// - Errors and notes are in argument order; for a switch given twice, the last value counts.
// - The typed getters read a value with the same function that accepted it (one rule).

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <string_view>
#include <vector>

#include "moos/limits.hpp"

namespace moos {

// ---- the typed switch table ------------------------------------------------------------------

/// What a switch takes.
enum class SwitchKind {
  kFlag,      ///< no value
  kText,      ///< a non-empty text (and SwitchRule::check, when set)
  kInteger,   ///< a whole number in the rule's range (base::parse_integer)
  kUnsigned,  ///< a whole number in [range.low, 2^64) (base::parse_unsigned)
  kNumber,    ///< a finite number in the rule's range (base::parse_number)
  kIgnored,   ///< accepted with or without a value, and ignored with a note
};

/// One switch of a program: how it is read and what is wrong with a refused value.
struct SwitchRule {
  std::string name;                  ///< as typed before any '=', e.g. "--moos_port"
  std::vector<std::string> aliases;  ///< other spellings, e.g. "-h"
  SwitchKind kind = SwitchKind::kFlag;
  Range range = kAnyNumber;          ///< kInteger, kNumber (kUnsigned: low only)
  std::function<bool(const std::string&)> check;  ///< kText: a further condition
  std::string problem;  ///< why a value is refused (kIgnored: why the switch is ignored)
};

/// A rule without aliases or a further check.
SwitchRule switch_rule(std::string name, SwitchKind kind, std::string problem,
                       Range range = kAnyNumber);

/// `--help` and `-h`, a flag: every program's help switch.
SwitchRule help_switch_rule();

/// `--version`, `-v` and `-version`, a flag: every program's version switch.
SwitchRule version_switch_rule();

/// A program's switches and its wording of the three errors.
struct SwitchTable {
  std::vector<SwitchRule> rules;
  /// A refused value: from the argument as typed and its rule.
  std::function<std::string(const std::string& argument, const SwitchRule&)> bad_value;
  /// A switch that needs `=value` given without one (empty: the `unknown` text).
  std::function<std::string(const std::string& argument, const SwitchRule&)> missing_value;
  /// A switch the table does not know.
  std::function<std::string(const std::string& argument)> unknown;
};

/// True when `rule` accepts `value` (see SwitchKind).
bool accepts(const SwitchRule& rule, const std::string& value);

/// What parse_switches read.
struct SwitchValues {
  std::map<std::string, std::string> values;  ///< by rule name (flags: ""); the last one counts
  std::vector<std::string> free;              ///< free arguments, in order
  std::vector<std::string> notes;             ///< ignored switches
  std::vector<std::string> errors;            ///< in argument order

  bool has(const std::string& name) const;
  std::optional<std::string> text(const std::string& name) const;
  std::optional<long long> integer(const std::string& name) const;
  std::optional<std::uint64_t> whole(const std::string& name) const;
  std::optional<double> number(const std::string& name) const;
};

/// True for `--NAME=value` with NAME a capital letter then letters, digits or '_': a mission
/// macro, as the offline tools (hazard_replay, hazard_study) take them beside their own
/// lower-case switches, so that a lower-case unknown switch stays an error (most likely a typo).
bool is_macro_argument(std::string_view arg);

/// Reads `args` (without argv[0]) with `table` (see the contract).
SwitchValues parse_switches(const std::vector<std::string>& args, const SwitchTable& table);

/// The rules of the generic MOOS switches that CommandLine types (their names without the
/// leading "--" are the keys of CommandLine::moos_switches).
const std::vector<SwitchRule>& generic_switch_rules();

// ---- the MOOS applications' command line --------------------------------------------------

struct CommandLine {
  std::optional<std::string> mission_file;
  std::optional<std::string> run_alias;     ///< from --alias= or the second free argument
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
  std::optional<int> moos_port;               ///< --moos_port, kConnectPortRange
  std::optional<double> moos_time_warp;       ///< --moos_time_warp, kTimeWarpRange
  std::optional<double> moos_app_tick_hz;     ///< --moos_app_tick, > 0 (MOOS-time Hz)
  std::optional<int> moos_comms_tick_hz;      ///< --moos_comms_tick N, kCommsTickRangeHz (4.2)

  /// Problems such as `--moos_port=abc`, each naming the argument.
  std::vector<std::string> errors;
};

/// Parses argv (argv[0] is the program). Never fails; problems go to `errors`.
CommandLine parse_command_line(int argc, const char* const* argv);
CommandLine parse_command_line(const std::vector<std::string>& args);

/// The run name: the alias if one was given, else `default_name` (protocol.md 6.4).
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
