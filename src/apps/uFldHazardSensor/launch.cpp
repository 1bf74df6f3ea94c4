#include "launch.hpp"

#include <optional>
#include <string_view>

#include "base/text.hpp"

namespace ufld_hazard_sensor {

namespace {

constexpr std::string_view kVerbose = "--verbose";

}  // namespace

Launch decide_launch_with_verbosity(const moos::CommandLine& cl) {
  Launch launch;
  for (const std::string& arg : cl.unhandled) {
    if (arg == kVerbose) {
      launch.verbose = true;
    } else if (base::starts_with(arg, std::string(kVerbose) + "=")) {
      const std::string value = arg.substr(kVerbose.size() + 1);
      const std::optional<bool> b = base::parse_bool(value);
      if (!b) {
        launch.action = LaunchAction::kUsageError;
        launch.error = "'" + arg + "': the verbosity must be true or false";
        return launch;
      }
      launch.verbose = *b;
    }
  }
  launch.action = moos::decide_launch(cl);
  return launch;
}

}  // namespace ufld_hazard_sensor
