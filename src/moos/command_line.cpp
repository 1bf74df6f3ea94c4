// Command-line conventions of MOOS programs (docs/protocol.md 6.4). Contract in
// include/moos/command_line.hpp.

#include "moos/command_line.hpp"

#include <algorithm>
#include <climits>

#include "moos/limits.hpp"
#include "base/text.hpp"

namespace moos {

namespace {

constexpr std::string_view kMoosPrefix = "--moos_";
constexpr std::string_view kAliasPrefix = "--alias=";
/// Switches that libMOOS reads as "switch followed by a separate argument" (protocol.md 6.4).
constexpr std::string_view kSwitchesWithNextArgument[] = {"moos_app_name", "moos_comms_tick"};

bool is_mission_name(std::string_view arg) {
  return base::ends_with(arg, ".moos") || base::ends_with(arg, ".moos++");
}

/// The generic switches' rules, the error wording of libMOOS programs: "<arg>: <problem>".
std::string bad_generic_value(const std::string& argument, const SwitchRule& rule) {
  return argument + ": " + rule.problem;
}

const SwitchRule* find_rule(const std::vector<SwitchRule>& rules, std::string_view name) {
  for (const SwitchRule& r : rules) {
    if (r.name == name) return &r;
    if (std::find(r.aliases.begin(), r.aliases.end(), name) != r.aliases.end()) return &r;
  }
  return nullptr;
}

/// An end of a range as a whole number (the ends of long long beyond them; an open end of a
/// kInteger rule is not used).
long long clamped_integer(double end) {
  constexpr double kLimit = 9.2e18;  // below 2^63, exact enough for any range we write
  if (end >= kLimit) return LLONG_MAX;
  if (end <= -kLimit) return LLONG_MIN;
  return static_cast<long long>(end);
}

/// A value that a kInteger rule accepted.
long long whole_number(const std::string& value) {
  return base::parse_integer(value, LLONG_MIN, LLONG_MAX).value_or(0);
}

/// Sets the typed field of a valid generic switch (`name` without the dashes).
void set_typed_switch(CommandLine& cl, const std::string& name, const std::string& value) {
  const SwitchRule* rule = find_rule(generic_switch_rules(), "--" + name);
  if (!rule) return;  // a generic switch that no field types
  if (!accepts(*rule, value)) {
    cl.errors.push_back(bad_generic_value("--" + name + "=" + value, *rule));
    return;
  }
  if (name == "moos_name") cl.moos_name = value;
  else if (name == "moos_app_name") cl.moos_app_name = value;
  else if (name == "moos_host") cl.moos_host = value;
  else if (name == "moos_file") cl.mission_file = value;
  else if (name == "moos_port") cl.moos_port = static_cast<int>(whole_number(value));
  else if (name == "moos_time_warp") cl.moos_time_warp = base::parse_number(value);
  else if (name == "moos_app_tick") cl.moos_app_tick_hz = base::parse_number(value);
  else if (name == "moos_comms_tick") cl.moos_comms_tick_hz = static_cast<int>(whole_number(value));
}

}  // namespace

SwitchRule switch_rule(std::string name, SwitchKind kind, std::string problem, Range range) {
  SwitchRule r;
  r.name = std::move(name);
  r.kind = kind;
  r.problem = std::move(problem);
  r.range = range;
  return r;
}

SwitchRule help_switch_rule() {
  SwitchRule r = switch_rule("--help", SwitchKind::kFlag, "");
  r.aliases = {"-h"};
  return r;
}

SwitchRule version_switch_rule() {
  SwitchRule r = switch_rule("--version", SwitchKind::kFlag, "");
  r.aliases = {"-v", "-version"};
  return r;
}

bool accepts(const SwitchRule& rule, const std::string& value) {
  switch (rule.kind) {
    case SwitchKind::kFlag: return value.empty();
    case SwitchKind::kIgnored: return true;
    case SwitchKind::kText: return !value.empty() && (!rule.check || rule.check(value));
    case SwitchKind::kInteger:
      return base::parse_integer(value, clamped_integer(rule.range.low),
                                 clamped_integer(rule.range.high))
          .has_value();
    case SwitchKind::kUnsigned: {
      const std::optional<std::uint64_t> v = base::parse_unsigned(value);
      return v && static_cast<double>(*v) >= rule.range.low;
    }
    case SwitchKind::kNumber: {
      const std::optional<double> v = base::parse_number(value);
      return v && rule.range.contains(*v);
    }
  }
  return false;
}

const std::vector<SwitchRule>& generic_switch_rules() {
  static const std::vector<SwitchRule> rules = {
      switch_rule("--moos_name", SwitchKind::kText, "empty name"),
      switch_rule("--moos_app_name", SwitchKind::kText, "empty name"),
      switch_rule("--moos_host", SwitchKind::kText, "empty host"),
      switch_rule("--moos_file", SwitchKind::kText, "empty file name"),
      switch_rule("--moos_port", SwitchKind::kInteger, "not a port number in 1..65535",
                  kConnectPortRange),
      switch_rule("--moos_time_warp", SwitchKind::kNumber,
                  "time warp must be a number in (0, 400]", kTimeWarpRange),
      switch_rule("--moos_app_tick", SwitchKind::kNumber, "AppTick must be a number > 0",
                  kPositive),
      switch_rule("--moos_comms_tick", SwitchKind::kInteger,
                  "CommsTick must be a whole number in 1..200", kCommsTickRangeHz),
  };
  return rules;
}

bool SwitchValues::has(const std::string& name) const { return values.count(name) != 0; }

std::optional<std::string> SwitchValues::text(const std::string& name) const {
  const auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

std::optional<long long> SwitchValues::integer(const std::string& name) const {
  const auto v = text(name);
  return v ? base::parse_integer(*v, LLONG_MIN, LLONG_MAX) : std::nullopt;
}

std::optional<std::uint64_t> SwitchValues::whole(const std::string& name) const {
  const auto v = text(name);
  return v ? base::parse_unsigned(*v) : std::nullopt;
}

std::optional<double> SwitchValues::number(const std::string& name) const {
  const auto v = text(name);
  return v ? base::parse_number(*v) : std::nullopt;
}

SwitchValues parse_switches(const std::vector<std::string>& args, const SwitchTable& table) {
  SwitchValues out;
  for (const std::string& arg : args) {
    if (arg.size() < 2 || arg[0] != '-') {
      out.free.push_back(arg);
      continue;
    }
    const auto eq = arg.find('=');
    const bool has_value = eq != std::string::npos;
    const std::string name = arg.substr(0, eq);
    const std::string value = has_value ? arg.substr(eq + 1) : std::string();
    const SwitchRule* rule = find_rule(table.rules, name);
    if (!rule || (rule->kind == SwitchKind::kFlag && has_value)) {
      out.errors.push_back(table.unknown(arg));
    } else if (rule->kind == SwitchKind::kIgnored) {
      out.notes.push_back(arg + " ignored: " + rule->problem);
    } else if (rule->kind != SwitchKind::kFlag && !has_value) {
      out.errors.push_back(table.missing_value ? table.missing_value(arg, *rule) : table.unknown(arg));
    } else if (!accepts(*rule, value)) {
      out.errors.push_back(table.bad_value(arg, *rule));
    } else {
      out.values[rule->name] = value;
    }
  }
  return out;
}

CommandLine parse_command_line(int argc, const char* const* argv) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) args.emplace_back(argv[i] ? argv[i] : "");
  return parse_command_line(args);
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  std::vector<std::string> free;
  std::optional<std::string> alias_flag;
  std::optional<std::string> moos_file;

  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (base::starts_with(arg, kAliasPrefix)) {
      alias_flag = arg.substr(kAliasPrefix.size());
      if (alias_flag->empty()) {
        cl.errors.push_back("--alias= needs a name");
        alias_flag.reset();
      }
      continue;
    }
    if (base::starts_with(arg, kMoosPrefix)) {
      const auto eq = arg.find('=');
      const std::string name = arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
      std::string value = eq == std::string::npos ? std::string() : arg.substr(eq + 1);
      const bool takes_next = std::find(std::begin(kSwitchesWithNextArgument),
                                        std::end(kSwitchesWithNextArgument),
                                        name) != std::end(kSwitchesWithNextArgument);
      if (takes_next && eq == std::string::npos) {
        if (i + 1 >= args.size()) {
          cl.errors.push_back("--" + name + " needs a value in the next argument");
          continue;
        }
        value = args[++i];
      }
      cl.moos_switches[name] = value;
      if (name == "moos_file") moos_file = value;
      if (eq != std::string::npos || takes_next) set_typed_switch(cl, name, value);
      continue;
    }
    if (!arg.empty() && arg[0] == '-') {
      const auto eq = arg.find('=');
      if (base::starts_with(arg, "--") && eq != std::string::npos && eq > 2)
        cl.substitutions[arg.substr(2, eq - 2)] = arg.substr(eq + 1);
      cl.unhandled.push_back(arg);
      continue;
    }
    free.push_back(arg);
  }

  // Mission file: first *.moos / *.moos++ argument, else the first free one (protocol.md 6.4).
  bool mission_is_second = false;  // then there is no positional alias
  std::size_t mission_index = free.size();  // free.size(): none
  for (std::size_t i = 0; i < free.size() && mission_index == free.size(); ++i)
    if (is_mission_name(free[i])) mission_index = i;
  if (mission_index == free.size() && !free.empty()) mission_index = 0;
  if (moos_file && !moos_file->empty()) {
    cl.mission_file = moos_file;  // every free argument stays visible to the application
  } else if (mission_index < free.size()) {
    cl.mission_file = free[mission_index];
    mission_is_second = mission_index == 1;
  }

  // Alias: the second free argument unless it is the mission file (pAntler convention).
  if (alias_flag) {
    cl.run_alias = alias_flag;
  } else if (free.size() > 1 && !mission_is_second) {
    cl.run_alias = free[1];
  }
  return cl;
}

std::string app_name_from(const CommandLine& cl, const std::string& default_name) {
  if (cl.run_alias) return *cl.run_alias;
  if (cl.moos_app_name) return *cl.moos_app_name;
  return default_name;
}

std::optional<InfoSwitch> information_switch(std::string_view arg) {
  if (arg == "-e" || arg == "--example" || arg == "-example") return InfoSwitch::kExample;
  if (arg == "-h" || arg == "--help" || arg == "-help") return InfoSwitch::kHelp;
  if (arg == "-i" || arg == "--interface") return InfoSwitch::kInterface;
  if (arg == "-v" || arg == "--version" || arg == "-version") return InfoSwitch::kVersion;
  return std::nullopt;
}

std::optional<InfoSwitch> first_information_switch(const CommandLine& cl) {
  for (const std::string& arg : cl.unhandled)
    if (auto info = information_switch(arg)) return info;
  return std::nullopt;
}

LaunchAction decide_launch(const CommandLine& cl) {
  const std::optional<InfoSwitch> info = first_information_switch(cl);
  if (!info) return cl.mission_file ? LaunchAction::kRun : LaunchAction::kHelp;
  switch (*info) {
    case InfoSwitch::kExample: return LaunchAction::kExample;
    case InfoSwitch::kHelp: return LaunchAction::kHelp;
    case InfoSwitch::kInterface: return LaunchAction::kInterface;
    case InfoSwitch::kVersion: return LaunchAction::kVersion;
  }
  return LaunchAction::kHelp;  // unreachable: every switch is listed
}

bool is_macro_argument(std::string_view arg) {
  if (arg.size() < 5 || arg.substr(0, 2) != "--" || arg[2] < 'A' || arg[2] > 'Z') return false;
  const auto eq = arg.find('=');
  if (eq == std::string_view::npos) return false;
  for (const char c : arg.substr(3, eq - 3)) {
    const bool word = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '_';
    if (!word) return false;
  }
  return true;
}

}  // namespace moos
