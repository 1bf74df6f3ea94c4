#pragma once
// The one start-up sequence of every MOOS application's main (uFldHazardSensor and the mission
// apps alike): read the command line, print an information text or a usage error, or print the
// launch line and run the app over TCP.
//
// Contract:
// - An application's own switches (the extension point `own_switches`, e.g. uFldHazardSensor's
//   --verbose) are read first; a non-empty answer is a usage error: "<app>: <answer> (see
//   --help)" on standard error, exit kExitUsageError.
// - Else the first information switch decides (decide_launch): its text on standard output,
//   exit 0 (1 if standard output fails). Without one and without a mission file, the help.
// - Else "<app> launching as <run name>" and a blank line (green when standard output is a
//   terminal, as MOOS-IvP apps print it), then the app built by `make_app` runs with run_app
//   until SIGINT or SIGTERM (run_app's exit code).

#include <functional>
#include <memory>
#include <string>

#include "moos/app.hpp"
#include "moos/command_line.hpp"

namespace moos {

/// Exit code of a usage error in an application's own switches.
inline constexpr int kExitUsageError = 2;

/// The information texts of one application.
struct InfoTexts {
  std::function<std::string()> help;
  std::function<std::string()> example;
  std::function<std::string()> interface;
  std::function<std::string()> version;
};

/// Reads an application's own switches: "" when they are fine, else the usage error (naming the
/// argument). It may keep what it read for `make_app`.
using OwnSwitches = std::function<std::string(const CommandLine&)>;

/// One application's start-up: its default process name, texts, switches and factory.
struct AppLaunch {
  std::string app_name;
  InfoTexts texts;
  std::function<std::unique_ptr<MoosApp>()> make_app;
  OwnSwitches own_switches;  ///< empty: the application has no switches of its own
};

/// What the command line asks for, and the usage error when there is one.
struct LaunchDecision {
  LaunchAction action = LaunchAction::kRun;
  std::string error;  ///< kUsageError: from own_switches
};

/// The decision of the contract, without printing or running anything.
LaunchDecision decide_launch(const CommandLine& command_line, const OwnSwitches& own_switches);

/// The whole of main (see the contract).
int launch(int argc, const char* const* argv, const AppLaunch& app);

}  // namespace moos
