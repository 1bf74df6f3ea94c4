// uFldHazardSensor: the simulated hazard sensor as a MOOS application (manual; spec 2; issue 4).
// main reads the command line, prints an information text or runs the app until SIGINT or
// SIGTERM. Exit codes: see help_text() (0, 1 from moos::run_app, kExitUsageError).

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "HazardSensor.hpp"
#include "HazardSensor_Info.hpp"
#include "launch.hpp"
#include "moos/command_line.hpp"
#include "moos/mission.hpp"

namespace {

using namespace ufld_hazard_sensor;

/// ANSI colours of the original's launch line (green on a terminal).
constexpr const char* kGreen = "\x1b[32m";
constexpr const char* kPlain = "\x1b[0m";

int print(const std::string& text) {
  std::cout << text << std::flush;
  return std::cout ? 0 : 1;
}

std::string folder_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

int main(int argc, char** argv) {
  const moos::CommandLine cl = moos::parse_command_line(argc, argv);
  const Launch launch = decide_launch(cl);
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

  HazardSensorOptions options;
  options.mission_directory = folder_of(*cl.mission_file);
  // The origin is a global of the mission file, not a block line: read it here (moos::run_app
  // reads the file again for the framework; a file it cannot read is reported there).
  moos::MissionOptions mission_options;
  mission_options.substitutions = cl.substitutions;
  if (const auto mission = moos::MissionFile::load(*cl.mission_file, mission_options, nullptr)) {
    options.origin = hazard::mission_origin(*mission);
  }
  if (launch.verbose) options.verbose = &std::cerr;
  HazardSensor app(std::move(options));
  return moos::run_app(app, cl, std::cout, std::cerr, terminal);
}
