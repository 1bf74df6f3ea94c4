// pLogLite: a logger writing pLogger's .alog format (docs/missions.md). main reads the
// command line, prints an information text or runs the app until SIGINT or SIGTERM (exit codes:
// moos::launch; after a stop, kExitLogNotWhole when records were lost).

#include <csignal>
#include <memory>

#include "LogLite.hpp"
#include "LogLite_Info.hpp"
#include "moos/launch.hpp"

int main(int argc, char** argv) {
  using namespace plog_lite;
  // A file size limit (ulimit -f) is then a write error the log counts, like a full disk,
  // instead of the end of the logger.
  std::signal(SIGXFSZ, SIG_IGN);
  const auto outcome = std::make_shared<LogOutcome>();
  moos::AppLaunch app;
  app.app_name = kAppName;
  app.texts = {help_text, example_text, interface_text, version_text};
  app.make_app = [outcome] { return std::make_unique<LogLite>(outcome); };
  const int code = moos::launch(argc, argv, app);
  // (launch has destroyed the app, and so closed the log, before it returns)
  return code == 0 && outcome->records_lost > 0 ? kExitLogNotWhole : code;
}
