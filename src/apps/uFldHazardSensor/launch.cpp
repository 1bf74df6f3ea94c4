#include "launch.hpp"

#include <optional>
#include <string_view>

#include "base/text.hpp"

namespace ufld_hazard_sensor {

namespace {

constexpr std::string_view kVerbose = "--verbose";

}  // namespace

moos::OwnSwitches verbose_switch(bool* verbose) {
  return [verbose](const moos::CommandLine& cl) -> std::string {
    *verbose = false;
    for (const std::string& arg : cl.unhandled) {
      if (arg == kVerbose) {
        *verbose = true;
      } else if (base::starts_with(arg, std::string(kVerbose) + "=")) {
        const std::optional<bool> b = base::parse_bool(arg.substr(kVerbose.size() + 1));
        if (!b) return "'" + arg + "': the verbosity must be true or false";
        *verbose = *b;
      }
    }
    return {};
  };
}

Launch decide_launch_with_verbosity(const moos::CommandLine& cl) {
  Launch launch;
  const moos::LaunchDecision decision = moos::decide_launch(cl, verbose_switch(&launch.verbose));
  launch.action = decision.action;
  launch.error = decision.error;
  return launch;
}

}  // namespace ufld_hazard_sensor
