// The start-up sequence of every MOOS application. Contract in include/moos/launch.hpp.

#include "moos/launch.hpp"

#include "base/diagnostics.hpp"

#include <unistd.h>

#include <iostream>

namespace moos {

namespace {

/// ANSI colours of the launch line (green on a terminal, as MOOS-IvP apps print it).
constexpr const char* kGreen = "\x1b[32m";
constexpr const char* kPlain = "\x1b[0m";

int print(const std::string& text) {
  std::cout << text << std::flush;
  return std::cout ? 0 : 1;
}

}  // namespace

LaunchDecision decide_launch(const CommandLine& cl, const OwnSwitches& own_switches) {
  LaunchDecision decision;
  if (own_switches) decision.error = own_switches(cl);
  decision.action = decision.error.empty() ? decide_launch(cl) : LaunchAction::kUsageError;
  return decision;
}

int launch(int argc, const char* const* argv, const AppLaunch& app) {
  const CommandLine cl = parse_command_line(argc, argv);
  const LaunchDecision decision = decide_launch(cl, app.own_switches);
  switch (decision.action) {
    case LaunchAction::kHelp: return print(app.texts.help());
    case LaunchAction::kExample: return print(app.texts.example());
    case LaunchAction::kInterface: return print(app.texts.interface());
    case LaunchAction::kVersion: return print(app.texts.version());
    case LaunchAction::kUsageError:
      std::cerr << app.app_name << ": " << decision.error << " (see --help)\n";
      return kExitUsageError;
    case LaunchAction::kRun: break;
  }
  // The terminal report and the warnings are diagnostics: a reader that stalls must not stop the
  // app (its mail, its postings, its signals).
  base::install_nonblocking_diagnostics(base::DiagnosticStreams::kStdoutAndStderr);
  const bool terminal = ::isatty(STDOUT_FILENO) != 0;
  std::cout << (terminal ? kGreen : "") << app.app_name << " launching as "
            << app_name_from(cl, app.app_name) << (terminal ? kPlain : "") << "\n\n"
            << std::flush;
  const std::unique_ptr<MoosApp> moos_app = app.make_app();
  return run_app(*moos_app, cl, std::cout, std::cerr, terminal);
}

}  // namespace moos
