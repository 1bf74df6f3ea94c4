#pragma once
// uFldHazardSensor's own switch, --verbose, plugged into the one start-up sequence of every MOOS
// app (moos::launch; manual 11, listing 11.4; docs/uFldHazardSensor.md; D29).
//
// Contract: `--verbose` and `--verbose=true` turn verbose on, `--verbose=false` off (case-
// insensitive; the last one wins); any other value is a usage error naming the argument, which
// beats every information switch. Everything else is moos::launch's: the first information
// switch decides, without one and without a mission file the help is shown, the mission file,
// the run alias (argv[2] or --alias=) and the --moos_* switches are parse_command_line's
// (docs/protocol.md 6.4). A `--verbose` is never a run alias (the original took it for one when
// it came second, D29). Other arguments are ignored, as in the original.

#include <string>

#include "moos/launch.hpp"

namespace ufld_hazard_sensor {

using moos::LaunchAction;

/// moos::launch's extension point for --verbose: stores the switch's value in `*verbose`
/// (false when absent) and answers "" or the usage error.
moos::OwnSwitches verbose_switch(bool* verbose);

/// The launch decision with the --verbose switch read (what main does, without running).
struct Launch {
  LaunchAction action = LaunchAction::kRun;
  bool verbose = false;
  std::string error;  ///< kUsageError: names the argument and why
};
Launch decide_launch_with_verbosity(const moos::CommandLine& command_line);

}  // namespace ufld_hazard_sensor
