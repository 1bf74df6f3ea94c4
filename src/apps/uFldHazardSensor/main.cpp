// uFldHazardSensor: the simulated hazard sensor as a MOOS application (manual; spec 2; issue 4).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM. Exit codes: see help_text() (0, 1 from moos::run_app, kExitUsageError).

#include <unistd.h>

#include <iostream>

#include "HazardSensor.hpp"
#include "HazardSensor_Info.hpp"
#include "launch.hpp"
#include "moos/command_line.hpp"

namespace {

using namespace ufld_hazard_sensor;

/// ANSI colours of the original's launch line (green on a terminal).
constexpr const char* kGreen = "\x1b[32m";
constexpr const char* kPlain = "\x1b[0m";

int print(const std::string& text) {
  std::cout << text << std::flush;
  return std::cout ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const moos::CommandLine cl = moos::parse_command_line(argc, argv);
  const Launch launch = decide_launch_with_verbosity(cl);
  switch (launch.action) {
    case LaunchAction::kHelp: return print(help_text());
    case LaunchAction::kExample: return print(example_text());
    case LaunchAction::kInterface: return print(interface_text());
    case LaunchAction::kVersion: return print(version_text());
    case LaunchAction::kUsageError:
      std::cerr << kAppName << ": " << launch.error << " (see --help)\n";
      return kExitUsageError;
    case LaunchAction::kRun: break;
  }

  const bool terminal = ::isatty(STDOUT_FILENO) != 0;
  const std::string name = moos::app_name_from(cl, kAppName);
  std::cout << (terminal ? kGreen : "") << kAppName << " launching as " << name
            << (terminal ? kPlain : "") << "\n\n"
            << std::flush;

  // moos::run_app reads the mission file: the block, its folder and the origin globals reach the
  // app through its settings.
  HazardSensorOptions options;
  if (launch.verbose) options.verbose = &std::cerr;
  HazardSensor app(std::move(options));
  return moos::run_app(app, cl, std::cout, std::cerr, terminal);
}
