#pragma once
// What main does with uFldHazardSensor's command line (manual 11, listing 11.4; spec 2; D29).
//
// Contract: arguments are read left to right and the first information switch decides
// (-e/--example/-example, -h/--help/-help, -i/--interface, -v/--version/-version), as in the
// original. `--verbose` and `--verbose=true` turn verbose on, `--verbose=false` off (case-
// insensitive; the last one wins); any other value is a usage error naming the argument.
// Without an information switch and without a mission file, the help is shown (the original's
// behaviour). The mission file, the run alias (argv[2] or --alias=) and the generic --moos_*
// switches are libmoos's parse_command_line's business (wire spec 6.4); a `--verbose` is never
// a run alias (the original took it for one when it came second, D29). Other arguments are
// ignored, as in the original.

#include <string>

#include "moos/command_line.hpp"

namespace ufld_hazard_sensor {

using moos::LaunchAction;

struct Launch {
  LaunchAction action = LaunchAction::kRun;
  bool verbose = false;
  std::string error;  ///< kUsageError: names the argument and why
};

Launch decide_launch_with_verbosity(const moos::CommandLine& command_line);

/// Exit code of a usage error (main prints the error and a pointer to --help).
inline constexpr int kExitUsageError = 2;

}  // namespace ufld_hazard_sensor
