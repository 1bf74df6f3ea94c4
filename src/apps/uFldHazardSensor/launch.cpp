#include "launch.hpp"

#include <optional>
#include <string_view>

#include "moos/text.hpp"

namespace ufld_hazard_sensor {

namespace {

constexpr std::string_view kVerbose = "--verbose";

/// The information switch `arg` names, if any (spec 2: `-interface` has no one-dash form).
std::optional<LaunchAction> information_switch(std::string_view arg) {
  if (arg == "-e" || arg == "--example" || arg == "-example") return LaunchAction::kExample;
  if (arg == "-h" || arg == "--help" || arg == "-help") return LaunchAction::kHelp;
  if (arg == "-i" || arg == "--interface") return LaunchAction::kInterface;
  if (arg == "-v" || arg == "--version" || arg == "-version") return LaunchAction::kVersion;
  return std::nullopt;
}

}  // namespace

Launch decide_launch(const moos::CommandLine& cl) {
  Launch launch;
  std::optional<LaunchAction> info;
  for (const std::string& arg : cl.unhandled) {
    if (!info) info = information_switch(arg);
    if (arg == kVerbose) {
      launch.verbose = true;
    } else if (moos::text::starts_with(arg, std::string(kVerbose) + "=")) {
      const std::string value = arg.substr(kVerbose.size() + 1);
      const std::optional<bool> b = moos::text::parse_bool(value);
      if (!b) {
        launch.action = LaunchAction::kUsageError;
        launch.error = "'" + arg + "': the verbosity must be true or false";
        return launch;
      }
      launch.verbose = *b;
    }
  }
  if (info) {
    launch.action = *info;
  } else if (!cl.mission_file) {
    launch.action = LaunchAction::kHelp;
  }
  return launch;
}

}  // namespace ufld_hazard_sensor
