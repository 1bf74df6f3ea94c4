// Command-line conventions of MOOS programs (wire spec 6.4). Contract in
// include/moos/command_line.hpp.

#include "moos/command_line.hpp"

#include <algorithm>

#include "moos/limits.hpp"
#include "base/text.hpp"

namespace moos {

namespace {

constexpr std::string_view kMoosPrefix = "--moos_";
constexpr std::string_view kAliasPrefix = "--alias=";
/// Switches that libMOOS reads as "switch followed by a separate argument" (spec 6.4).
constexpr std::string_view kSwitchesWithNextArgument[] = {"moos_app_name", "moos_comms_tick"};

bool is_mission_name(std::string_view arg) {
  return base::ends_with(arg, ".moos") || base::ends_with(arg, ".moos++");
}

void set_typed_switch(CommandLine& cl, const std::string& name, const std::string& value) {
  auto bad = [&](const std::string& why) {
    cl.errors.push_back("--" + name + "=" + value + ": " + why);
  };
  if (name == "moos_name") {
    if (value.empty()) bad("empty name"); else cl.moos_name = value;
  } else if (name == "moos_app_name") {
    if (value.empty()) bad("empty name"); else cl.moos_app_name = value;
  } else if (name == "moos_host") {
    if (value.empty()) bad("empty host"); else cl.moos_host = value;
  } else if (name == "moos_community") {
    if (value.empty()) bad("empty community"); else cl.moos_community = value;
  } else if (name == "moos_file") {
    if (value.empty()) bad("empty file name"); else cl.mission_file = value;
  } else if (name == "moos_port") {
    if (auto p = base::parse_integer(value, 1, kMaxPort)) cl.moos_port = static_cast<int>(*p);
    else bad("not a port number in 1..65535");
  } else if (name == "moos_time_warp") {
    if (const auto w = parse_time_warp(value)) cl.moos_time_warp = *w;
    else bad("time warp must be a number in (0, 400]");
  } else if (name == "moos_app_tick") {
    const auto f = base::parse_number(value);
    if (f && *f > 0) cl.moos_app_tick_hz = *f;
    else bad("AppTick must be a number > 0");
  } else if (name == "moos_comms_tick") {
    if (auto t = base::parse_integer(value, 1, kMaxCommsTickHz)) cl.moos_comms_tick_hz = static_cast<int>(*t);
    else bad("CommsTick must be a whole number in 1..200");
  } else if (name == "moos_timeout") {
    const auto t = base::parse_number(value);
    if (t && *t > 0) cl.moos_timeout_s = *t;
    else bad("timeout must be a number > 0");
  }
}

}  // namespace

bool CommandLine::has_flag(const std::string& flag, const std::vector<std::string>& aliases) const {
  for (const auto& arg : unhandled) {
    if (arg == flag) return true;
    if (std::find(aliases.begin(), aliases.end(), arg) != aliases.end()) return true;
  }
  return false;
}

std::optional<std::string> CommandLine::flag_value(const std::string& name) const {
  std::optional<std::string> found;
  const std::string prefix = name + "=";
  for (const auto& arg : unhandled)
    if (base::starts_with(arg, prefix)) found = arg.substr(prefix.size());
  return found;
}

CommandLine parse_command_line(int argc, const char* const* argv) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) args.emplace_back(argv[i] ? argv[i] : "");
  return parse_command_line(args);
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  if (!args.empty()) cl.program = args[0];
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

  // Mission file: first *.moos / *.moos++ argument, else the first free one (spec 6.4).
  // `taken[i]` marks the free arguments consumed as mission file or alias.
  std::vector<bool> taken(free.size(), false);
  std::size_t mission_index = free.size();  // free.size(): none
  for (std::size_t i = 0; i < free.size() && mission_index == free.size(); ++i)
    if (is_mission_name(free[i])) mission_index = i;
  if (mission_index == free.size() && !free.empty()) mission_index = 0;
  if (moos_file && !moos_file->empty()) {
    cl.mission_file = moos_file;  // every free argument stays visible to the application
  } else if (mission_index < free.size()) {
    cl.mission_file = free[mission_index];
    taken[mission_index] = true;
  }

  // Alias: the second free argument unless it is the mission file (pAntler convention).
  if (alias_flag) {
    cl.run_alias = alias_flag;
  } else if (free.size() > 1 && !taken[1]) {
    cl.run_alias = free[1];
    taken[1] = true;
  }

  for (std::size_t i = 0; i < free.size(); ++i)
    if (!taken[i]) cl.extra_arguments.push_back(free[i]);
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

}  // namespace moos
